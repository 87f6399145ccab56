# The sidebar panel (3D view, N panel, tab "probeproxy"): the scene's operators, the active
# probe's settings and its last built proxy, and the validation's findings.

import json

import bpy

from . import native


class _Sidebar:
    """Where every probeproxy panel lives: the 3D view's sidebar, tab "probeproxy"."""
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "probeproxy"


class PROBEPROXY_PT_main(_Sidebar, bpy.types.Panel):
    bl_label = "probeproxy"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.probeproxy
        if native.module is None:
            box = layout.box()
            box.alert = True
            for i, line in enumerate(_wrap(native.problem, 48)):
                box.label(text=line, icon="ERROR" if i == 0 else "NONE")
            return
        width = _chars(context)
        col = layout.column(align=True)
        col.operator("probeproxy.import_scene", icon="IMPORT")
        col.operator("probeproxy.save_scene", icon="FILE_TICK")
        col.operator("probeproxy.add_probe", icon="LIGHTPROBE_CUBEMAP")
        col.separator()
        col.prop(settings, "tolerance_deg")
        col.prop(settings, "max_planes")
        col.prop(settings, "regenerate")
        # Which level objects the operators build from, always in view.
        box = layout.box()
        box.label(text="Build from:")
        box.row(align=True).prop(settings, "level_scope", expand=True)
        from .operators import _level_objects
        chosen = _level_objects(context)
        if settings.level_scope == "SELECTED":
            if not chosen:
                sub = box.column()
                sub.alert = True
                sub.label(text="No level object selected", icon="ERROR")
            for line in _wrap(", ".join(sorted(o.name for o in chosen)), width - 2)[:4]:
                box.label(text=line)
        else:
            box.label(text="All %d level objects" % len(chosen))
        col = layout.column(align=True)
        col.operator("probeproxy.generate_proxies", icon="MESH_ICOSPHERE")
        col.operator("probeproxy.validate_volumes", icon="CHECKMARK")
        col.operator("probeproxy.export_proxies", icon="EXPORT")
        row = col.row(align=True)
        row.operator("probeproxy.eevee_probes", icon="LIGHTPROBE_CUBEMAP")
        row.operator("probeproxy.eevee_probes_from_file", text="", icon="FILEBROWSER")
        col = layout.column(align=True)
        col.prop(settings, "layout_tolerance_deg")
        col.prop(settings, "layout_max_probes")
        col.operator("probeproxy.suggest_probes", icon="OUTLINER_OB_LIGHTPROBE")
        if settings.layout_summary:
            for line in _wrap(settings.layout_summary, width):
                col.label(text=line)
            image = bpy.data.images.get(bpy.path.basename(settings.layout_map))
            if image is not None:
                image.preview_ensure()
                col.template_icon(icon_value=image.preview.icon_id, scale=12.0)
        col.prop(settings, "show_volumes")
        if settings.scene_file:
            for line in _wrap("Scene: " + bpy.path.basename(settings.scene_file), width):
                layout.label(text=line)
        if settings.level_used:
            for line in _wrap("Last built from " + settings.level_used, width):
                layout.label(text=line)


class PROBEPROXY_PT_probe(_Sidebar, bpy.types.Panel):
    bl_label = "Probe"
    bl_parent_id = "PROBEPROXY_PT_main"

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.probeproxy.is_probe

    def draw(self, context):
        layout = self.layout
        obj = context.active_object
        s = obj.probeproxy
        layout.label(text=obj.name, icon="LIGHTPROBE_CUBEMAP")
        if s.result_json:  # the last Generate's figures first: what an artist looks for
            r = json.loads(s.result_json)
            e = r["error"]
            box = layout.box()
            # Short lines: the sidebar's default width holds about 30 characters.
            box.label(text="Kept: %s (%s)" % (r["candidate"], r["kind"]))
            box.label(text="%d planes, %d vertices" % (r["planes"], r["vertices"]))
            box.label(text="p95 %s deg" % _deg(e["p95_deg"]))
            box.label(text="median %s deg" % _deg(e["median_deg"]))
            box.label(text="max %s deg" % _deg(e["max_deg"]))
            box.label(text="miss %.2f%%, occluded %.2f%%" % (
                100 * e["miss_rate"], 100 * e["occluded_rate"]))
            box.label(text="%d mirror_floor samples" % e["samples"])
            for finding in r.get("findings", []):
                for i, line in enumerate(_wrap(finding, _chars(context) - 4)):
                    box.label(text=line, icon="ERROR" if i == 0 else "BLANK1")
        if s.proxy_mode == "MESH" and s.proxy_mesh.endswith("_proxy_edited.obj"):
            for i, line in enumerate(_wrap("Proxy: your edit of the generated mesh, exported as "
                                           "authored (" + s.proxy_mesh + ")", _chars(context) - 4)):
                layout.label(text=line, icon="GREASEPENCIL" if i == 0 else "BLANK1")
        # Each vector under its own label, its components stacked: at the sidebar's default
        # width a label beside three fields leaves room for neither.
        if obj.parent is None:
            _vector(layout, obj, "location", "Capture")
        else:
            # The library captures at the world location; the field edits the local one.
            units = context.scene.unit_settings
            world = ", ".join(bpy.utils.units.to_string(units.system, "LENGTH",
                                                        c * units.scale_length, precision=3)
                              for c in obj.matrix_world.translation)
            for i, line in enumerate(_wrap("Capture (world): " + world, _chars(context) - 2)):
                layout.label(text=line)
            _vector(layout, obj, "location", "Location under " + obj.parent.name)
        layout.label(text="Influence:")
        layout.prop(s, "influence_shape", text="")
        _vector(layout, s, "influence_offset", "Centre offset")
        if s.influence_shape == "BOX":
            _vector(layout, s, "half_extents", "Outer half-extents")
            _vector(layout, s, "inner_half_extents", "Inner half-extents")
        else:
            layout.prop(s, "radius")
            layout.prop(s, "inner_radius")
        layout.label(text="Proxy:")
        layout.prop(s, "proxy_mode", text="")
        if s.proxy_mode == "BOX":
            _vector(layout, s, "proxy_center", "Proxy centre")
            _vector(layout, s, "proxy_half_extents", "Proxy half-extents")
            _vector(layout, s, "proxy_rotation", "Proxy rotation (w, x, y, z)")
        elif s.proxy_mode == "SPHERE":
            _vector(layout, s, "proxy_center", "Proxy centre")
            layout.prop(s, "proxy_radius", text="Radius")
        elif s.proxy_mode == "MESH":
            layout.prop(s, "proxy_mesh", text="")
        elif s.proxy_mode == "CHEAP_K":
            layout.prop(s, "proxy_k", text="k (per unit)")


def _vector(layout, data, name, label):
    col = layout.column(align=True)
    col.label(text=label)
    col.prop(data, name, text="")


class PROBEPROXY_PT_findings(_Sidebar, bpy.types.Panel):
    bl_label = "Findings"
    bl_parent_id = "PROBEPROXY_PT_main"

    @classmethod
    def poll(cls, context):
        return context.scene.probeproxy.validated

    def draw(self, context):
        from .operators import findings_summary
        findings = context.scene.probeproxy.findings
        width = _chars(context)
        if not findings:
            self.layout.label(text="No findings: every volume passes", icon="CHECKMARK")
            return
        summary = findings_summary([f.severity for f in findings])
        head, _, counts = summary.partition(" (")
        self.layout.label(text=head, icon="ERROR")
        if counts:
            self.layout.label(text=counts.rstrip(")"))
        icons = {"error": "CANCEL", "warning": "ERROR", "info": "INFO"}
        for f in findings:
            box = self.layout.box()
            box.label(text="%s: %s" % (f.severity, f.probe or "scene"),
                      icon=icons.get(f.severity, "INFO"))
            for line in _wrap(f.rule, width):
                box.label(text=line)
            if f.value != "null" or f.limit != "null":
                box.label(text="value %s / limit %s" % (_number(f.value), _number(f.limit)))
            col = box.column(align=True)
            for line in _wrap(f.message, width):
                col.label(text=line)
            if f.hint:
                for i, line in enumerate(_wrap("Fix: " + f.hint, width - 4)):
                    col.label(text=line, icon="LIGHT" if i == 0 else "BLANK1")


def _number(text):
    """A finding's value or limit (JSON text) as the CLI prints it: 4 significant digits."""
    value = json.loads(text or "null")
    return "-" if value is None else "%.4g" % value


def _chars(context):
    """Characters that fit on one line of the sidebar (about 7 px each at 1x scale)."""
    region = context.region
    scale = context.preferences.system.ui_scale
    return max(24, int((region.width if region else 300) / (7 * scale)) - 4)


def _deg(value):
    return "-" if value is None else "%.3f" % value


def _wrap(text, width):
    import textwrap
    return textwrap.wrap(text, width) or [""]


classes = (PROBEPROXY_PT_main, PROBEPROXY_PT_probe, PROBEPROXY_PT_findings)


register, unregister = bpy.utils.register_classes_factory(classes)

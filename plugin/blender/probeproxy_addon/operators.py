# The add-on's operators, all under bpy.ops.probeproxy.*. Each one calls the compiled library
# (native.module) with plain data and turns its InputError into a report the user sees.

import json
import math
import os
import tempfile

import bpy
from bpy.props import BoolProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper
from mathutils import Matrix

from . import background_job, eevee_probes, native, scene_io
from .artist_message import artist_message


class _OpensJson(ImportHelper):
    """An operator that reads a .json file chosen in the file browser."""
    filename_ext = ".json"
    filter_glob: StringProperty(default="*.json", options={"HIDDEN"})


class _NeedsModule:
    @classmethod
    def poll(cls, context):
        if native.module is None:
            cls.poll_message_set(native.problem)
            return False
        return True


def _run(operator, work):
    """Runs `work()`; bad input becomes an error report with the library's message, as the
    artist's scene says it, and any other failure (a folder that cannot be written, a bug) one
    line naming the operator, never a traceback in the artist's face."""
    try:
        return work()
    except native.module.InputError as e:
        operator.report({"ERROR"}, artist_message(bpy.context.scene, str(e)))
        return {"CANCELLED"}
    except Exception as e:  # noqa: BLE001: every failure becomes one line
        text = " ".join(str(e).split()) or type(e).__name__
        operator.report({"ERROR"}, "%s failed: %s" % (operator.bl_label, text))
        return {"CANCELLED"}


def _build_options(settings):
    return {"tolerance_deg": scene_io.f32(settings.tolerance_deg),
            "max_planes": settings.max_planes, "regenerate": settings.regenerate}


def _level_objects(context):
    """The level objects to work on: the whole level, unless the artist asked in the panel for
    the selected objects only (Level: Selected). Never narrowed silently by a stale selection."""
    if context.scene.probeproxy.level_scope == "SELECTED":
        return [o for o in context.selected_objects if scene_io.is_level_object(o)]
    return [o for o in context.scene.objects if scene_io.is_level_object(o)]


def _no_level_message(context):
    if context.scene.probeproxy.level_scope == "SELECTED":
        return "no level: Level is set to Selected and no level mesh is selected"
    return "no level: the scene has no mesh objects besides probes and proxies"


def _with_progress(context, work):
    """Runs work(progress) with Blender's progress bar following the library's (done, total)
    reports, whatever the total: probes for a build, steps for a layout."""
    wm = context.window_manager
    wm.progress_begin(0, 1000)
    try:
        return work(lambda done, total: wm.progress_update(int(1000 * done / max(total, 1))))
    finally:
        wm.progress_end()


class _LibraryJob(background_job.ModalJob):
    """An operator whose library call runs as a job (background_job.py)."""
    run_guarded = staticmethod(_run)
    with_progress = staticmethod(_with_progress)


def _remove_probe(probe):
    proxy = probe.probeproxy.proxy_object
    if proxy is not None:
        mesh = proxy.data
        bpy.data.objects.remove(proxy)
        if mesh is not None and mesh.users == 0:
            bpy.data.meshes.remove(mesh)
    bpy.data.objects.remove(probe)


def _proxy_mesh_object(scene, probe, result):
    """The kept proxy as a mesh object (Blender units), with a fingerprint of it as made, so that
    a hand edit is found later (_take_edited_proxies)."""
    name = probe.name + "_proxy"
    old = probe.probeproxy.proxy_object
    if old is not None:
        mesh = old.data
        bpy.data.objects.remove(old)
        if mesh is not None and mesh.users == 0:
            bpy.data.meshes.remove(mesh)
    data = result["mesh"]
    if not data["vertices"]:
        probe.probeproxy.proxy_object = None
        return None
    k = scene_io.meters_per_bu(scene)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(scene_io.to_bu(list(v), k)) for v in data["vertices"]], [],
                     [tuple(t) for t in data["triangles"]])
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.probeproxy.is_proxy = True
    obj.display_type = "WIRE"
    obj.show_in_front = True
    obj["probeproxy_probe"] = probe.name
    scene_io.collection(scene, "Proxies").objects.link(obj)
    probe.probeproxy.proxy_object = obj
    probe.probeproxy.proxy_fingerprint = scene_io.mesh_fingerprint(obj, probe)
    return obj


def _take_build_result(scene, probe, result):
    """A probe's build result (build_proxies' or suggest_probes'): its figures for the panel and
    its kept proxy as a mesh object."""
    probe.probeproxy.result_json = json.dumps(result["proxy"] | {
        "error": result["error"], "findings": result["findings"],
        "candidates": [{k: c[k] for k in ("kind", "planes", "error")} for c in result["candidates"]]})
    _proxy_mesh_object(scene, probe, result)


EDITED_HEADER = "# probeproxy: the hand-edited proxy of probe "


def _write_edited_proxy(path, obj, meters_per_unit, probe_name):
    """Writes the proxy object's world-space triangles as an OBJ in metres (Z up, the scene
    dict's frame). Refuses to overwrite a file that is not one of these."""
    if os.path.exists(path):
        with open(path, errors="replace") as f:
            if not f.readline().startswith(EDITED_HEADER):
                raise native.module.InputError(
                    "%s: exists and is not a probeproxy hand-edited proxy; not overwritten" % path)
    m = obj.matrix_world
    lines = [EDITED_HEADER + probe_name + "\n"]
    for v in obj.data.vertices:
        p = m @ v.co
        lines.append("v %r %r %r\n" % tuple(float(c) * meters_per_unit for c in p))
    for poly in obj.data.polygons:
        lines.append("f " + " ".join(str(i + 1) for i in poly.vertices) + "\n")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.writelines(lines)
    os.replace(tmp, path)


def _take_edited_proxies(operator, context):
    """A generated proxy the artist edited is the artist's from then on: its mesh is written
    beside the scene (<probe>_proxy_edited.obj, metres) and the probe's proxy becomes that
    authored convex mesh, measured and validated like any authored proxy, so no operator
    throws the edit away. Returns the probes taken."""
    scene = context.scene
    k = scene_io.meters_per_bu(scene)
    folder = os.path.dirname(scene_io.scene_anchor(scene))
    taken = []
    for probe in scene_io.probes(scene):
        s = probe.probeproxy
        obj = s.proxy_object
        if obj is None or not s.proxy_fingerprint:
            continue
        if obj.mode == "EDIT":
            obj.update_from_editmode()
        if scene_io.mesh_fingerprint(obj, probe) == s.proxy_fingerprint:
            continue
        path = os.path.join(folder, probe.name + "_proxy_edited.obj")
        _write_edited_proxy(path, obj, k, probe.name)
        s.proxy_mode = "MESH"
        s.proxy_mesh = os.path.basename(path)  # relative to the scene file, as the file has it
        s.proxy_fingerprint = scene_io.mesh_fingerprint(obj, probe)
        taken.append(probe.name)
    if taken:
        operator.report({"INFO"}, "hand-edited proxies kept as authored meshes: " +
                        ", ".join(taken))
    return taken


def _probes_and_level(operator, context):
    """The level objects to work on, or None (reported) when the scene has no probe or no
    level."""
    if not scene_io.probes(context.scene):
        operator.report({"ERROR"}, "no probes: add one with Add Probe or import a scene")
        return None
    objects = _level_objects(context)
    if not objects:
        operator.report({"ERROR"}, _no_level_message(context))
        return None
    return objects


def _build_input(operator, context):
    """What a build of the scene's probes hands the library: the level's parts (the artist's
    edited proxies taken first), what they came from, the scene dict, its anchor and the build
    options; None (reported) when there are no probes or no level."""
    scene = context.scene
    objects = _probes_and_level(operator, context)
    if objects is None:
        return None
    _take_edited_proxies(operator, context)
    parts, used = scene_io.level_parts(context, objects)
    return (parts, used, scene_io.scene_dict(scene), scene_io.scene_anchor(scene),
            _build_options(scene.probeproxy))


def _build_findings(settings, results):
    """The build's findings (capture point outside the level, kept proxy not around the capture
    point...) as warnings in the Findings list, where Validate's go: not a line that is gone in
    a second."""
    settings.findings.clear()
    count = 0
    for result in results:
        for message in result["findings"]:
            item = settings.findings.add()
            item.probe = result["name"]
            item.rule = "build"
            item.severity = "warning"
            item.value = item.limit = "null"
            item.message = message
            item.hint = "see the probe's figures under Probe; move the capture point into the level"
            count += 1
    settings.validated = True
    return count


class PROBEPROXY_OT_generate_proxies(_NeedsModule, _LibraryJob, bpy.types.Operator):
    """Build every probe's convex proxy from the level (the whole level, or the selected level
    objects when Level is set to Selected) and add it as a mesh in the "Proxies" collection"""
    bl_idname = "probeproxy.generate_proxies"
    bl_label = "Generate Proxies"
    bl_options = {"REGISTER", "UNDO"}

    def steps(self, context):
        # A failure must not leave the last success's "Last built from" on show.
        context.scene.probeproxy.level_used = ""
        scene = context.scene
        settings = scene.probeproxy
        probes = scene_io.probes(scene)
        built = _build_input(self, context)
        if built is None:
            return {"CANCELLED"}
        parts, used, scene_data, anchor, options = built
        results = yield lambda progress: native.module.build_proxies(
            scene_data, anchor, parts, options, progress)
        by_name = {p.name: p for p in probes}
        for result in results:
            _take_build_result(scene, by_name[result["name"]], result)
        settings.level_used = used
        warnings = _build_findings(settings, results)
        if warnings:
            self.report({"WARNING"}, "built %d proxies from %s; %d finding%s (see Findings)"
                        % (len(results), used, warnings, "" if warnings == 1 else "s"))
        else:
            self.report({"INFO"}, "built %d proxies from %s" % (len(results), used))
        return {"FINISHED"}


class PROBEPROXY_OT_suggest_probes(_NeedsModule, _LibraryJob, bpy.types.Operator):
    """Lay out probes for the whole level, as `probeproxy layout` does: the fewest that serve
    the walkable floor within the layout tolerance, each with an influence box and its proxy.
    They replace the scene's probes, which seed the floor where the level has no spawn points
    (Ctrl+Z brings them back); the error map shows in the panel"""
    bl_idname = "probeproxy.suggest_probes"
    bl_label = "Suggest Probes"
    bl_options = {"REGISTER", "UNDO"}

    def steps(self, context):
        # A failure must not leave the last success's "Last built from" on show.
        context.scene.probeproxy.level_used = ""
        scene = context.scene
        settings = scene.probeproxy
        objects = _level_objects(context)
        if not objects:
            self.report({"ERROR"}, _no_level_message(context))
            return {"CANCELLED"}

        _take_edited_proxies(self, context)
        parts, used = scene_io.level_parts(context, objects)
        anchor = scene_io.scene_anchor(scene)
        out = os.path.splitext(os.path.splitext(anchor)[0])[0] + "_layout"
        options = {"tolerance_deg": scene_io.f32(settings.layout_tolerance_deg)}
        if settings.layout_max_probes:
            options["max_probes"] = settings.layout_max_probes
        # A new layout starts from the probes the artist has now, not the last layout's floor.
        current = scene_io.scene_dict(scene)
        current.pop("measured_with", None)
        result = yield lambda progress: native.module.suggest_probes(
            current, anchor, out, parts, options, progress)
        for old in scene_io.probes(scene):
            _remove_probe(old)
        coll = scene_io.collection(scene, "Probes")
        k = scene_io.meters_per_bu(scene)
        for order, (d, built) in enumerate(zip(result["scene"]["probes"], result["probes"])):
            obj = bpy.data.objects.new(d["name"], None)
            obj.empty_display_type = "PLAIN_AXES"
            obj.empty_display_size = 0.25
            coll.objects.link(obj)
            if isinstance(d["proxy"], dict) and "mesh" in d["proxy"]:
                # The layout's proxy files are in `out`; the scene's paths are the anchor's.
                d["proxy"]["mesh"] = os.path.relpath(os.path.join(out, d["proxy"]["mesh"]),
                                                     os.path.dirname(anchor))
            scene_io.set_probe_from_dict(obj, d, k)
            obj.probeproxy.order = order
            _take_build_result(scene, obj, built)
        settings.measured_with_json = json.dumps(result["scene"].get("measured_with", {}))
        figures = result["figures"]["survey"]
        maps = [f for f in result["files"] if f.endswith(".png")]
        settings.layout_map = maps[0] if maps else ""
        if maps:
            bpy.data.images.load(maps[0], check_existing=True).reload()
        settings.layout_summary = "%d probes: p95 %.1f deg, %.1f%% of the floor over %.3g deg" % (
            len(result["probes"]), figures["p95_deg"] or 0.0,
            100 * figures["over_tolerance_share"], settings.layout_tolerance_deg)
        settings.level_used = used
        settings.findings.clear()
        settings.validated = False
        self.report({"INFO"}, "suggested " + settings.layout_summary + " (files in %s)" % out)
        return {"FINISHED"}


def findings_summary(severities):
    """One line for the status bar, counted as `probeproxy validate` counts them."""
    if not severities:
        return "clean: no findings"
    n = len(severities)
    return "%d finding%s (%d error, %d warning, %d info)" % (
        n, "" if n == 1 else "s", severities.count("error"), severities.count("warning"),
        severities.count("info"))


def _select_probes(context, names, first):
    """Selects exactly the probes named (the offending ones); `first` becomes active."""
    for obj in context.view_layer.objects:
        obj.select_set(obj.probeproxy.is_probe and obj.name in names)
    active = context.view_layer.objects.get(first or "")
    if active is not None and active.probeproxy.is_probe:
        context.view_layer.objects.active = active


class PROBEPROXY_OT_validate_volumes(_NeedsModule, bpy.types.Operator):
    """Check the probes' proxies and influence volumes against the level (whole, or selected
    when Level is set to Selected), as `probeproxy validate` does; list the findings and
    select the probes they name"""
    bl_idname = "probeproxy.validate_volumes"
    bl_label = "Validate Volumes"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        # A failure must not leave the last success's "Last built from" on show.
        context.scene.probeproxy.level_used = ""
        scene = context.scene
        settings = scene.probeproxy
        objects = _probes_and_level(self, context)
        if objects is None:
            return {"CANCELLED"}

        def work():
            _take_edited_proxies(self, context)
            parts, used = scene_io.level_parts(context, objects)
            current = scene_io.scene_dict(scene)
            # A laid-out scene is judged by the tolerance its layout was made for, as
            # `probeproxy validate` judges it; else by the panel's.
            options = {}
            if "tolerance_deg" not in current.get("measured_with", {}):
                options["tolerance_deg"] = scene_io.f32(settings.tolerance_deg)
            findings = native.module.validate_scene(
                current, scene_io.scene_anchor(scene), parts, options)
            settings.findings.clear()
            for f in findings:
                item = settings.findings.add()
                for key in ("probe", "rule", "severity", "message", "hint"):
                    setattr(item, key, f[key])
                # As the report's JSON text: a float property would round them to 32 bits.
                item.value = json.dumps(f["value"])
                item.limit = json.dumps(f["limit"])
            settings.validated = True
            settings.level_used = used
            _select_probes(context, {f["probe"] for f in findings},
                           findings[0]["probe"] if findings else None)
            summary = findings_summary([f["severity"] for f in findings])
            failing = any(f["severity"] in ("error", "warning") for f in findings)
            self.report({"WARNING" if failing else "INFO"}, "Validate: " + summary)
            return {"FINISHED"}

        return _run(self, work)


class PROBEPROXY_OT_export_proxies(_NeedsModule, _LibraryJob, bpy.types.Operator):
    """Write proxies.json and proxies.glb for the game runtime into a folder"""
    bl_idname = "probeproxy.export_proxies"
    bl_label = "Export Proxies"
    bl_options = {"REGISTER"}

    directory: StringProperty(name="Folder", subtype="DIR_PATH")

    def invoke(self, context, event):
        self._modal_wanted = True  # once the folder is chosen, as a job with progress and Esc
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}

    def steps(self, context):
        scene = context.scene
        if not self.directory:
            self.report({"ERROR"}, "no folder: choose the folder to write proxies.json into")
            return {"CANCELLED"}
        built = _build_input(self, context)
        if built is None:
            return {"CANCELLED"}
        parts, used, scene_data, anchor, options = built
        out = bpy.path.abspath(self.directory)
        results = yield lambda progress: native.module.export_proxies(
            scene_data, anchor, out, parts, options, progress)
        scene.probeproxy.level_used = used
        self.report({"INFO"}, "wrote %d probes to %s (level: %s)" % (
            len(results), os.path.join(out, "proxies.json"), used))
        return {"FINISHED"}


def _import_level_mesh(path, up, meters_per_unit, meters_per_bu):
    """Imports one level mesh with Blender's importer; returns the objects it made.
    `meters_per_unit`: the scene file's unit; `meters_per_bu`: the Blender scene's Unit Scale.
    Blender's glTF importer already turns metres into Blender units (it divides by the Unit
    Scale, io_scene_gltf2 gltf2_blender_gltf.py); the OBJ and PLY importers do not."""
    before = set(bpy.data.objects)
    ext = os.path.splitext(path)[1].lower()
    if ext in (".glb", ".gltf"):
        import numpy as np  # Debian's numpy dropped np.bool; Blender 3.4's importer uses it
        if "bool" not in vars(np):
            np.bool = bool
        bpy.ops.import_scene.gltf(filepath=path)
        file_up = "Y"  # the importer turns glTF's +Y up into Blender's +Z
        to_bu = meters_per_unit
    elif ext == ".obj":
        bpy.ops.wm.obj_import(filepath=path, up_axis=up, forward_axis="NEGATIVE_Z" if up == "Y" else "Y")
        file_up = up
        to_bu = meters_per_unit / meters_per_bu
    elif ext == ".ply":
        bpy.ops.import_mesh.ply(filepath=path, axis_up=up, axis_forward="-Z" if up == "Y" else "Y")
        file_up = up
        to_bu = meters_per_unit / meters_per_bu
    else:
        raise native.module.InputError("%s: Blender has no importer for %s meshes" % (path, ext))
    made = [o for o in bpy.data.objects if o not in before]
    fix = Matrix.Scale(to_bu, 4)
    if up != file_up:  # the scene says the file's up differs from what the importer assumed
        fix = fix @ Matrix.Rotation(math.pi / 2 if up == "Y" else -math.pi / 2, 4, "X")
    if fix != Matrix.Identity(4):
        for obj in made:
            if obj.parent is None:
                obj.matrix_world = fix @ obj.matrix_world
    return made


def import_scene(context, path):
    """Reads a scene file into Blender: its level meshes (Blender's importers), one empty per
    probe. Raises InputError for a bad scene file."""
    path = os.path.abspath(path)
    module = native.module
    as_written = module.read_scene(path)
    world = module.read_scene(path, world_frame=True)
    scene = context.scene
    settings = scene.probeproxy
    level_coll = scene_io.collection(scene, "Level")
    probe_coll = scene_io.collection(scene, "Probes")
    folder = os.path.dirname(path)
    depsgraph = None
    for index, entry in enumerate(as_written["level"]):
        entry = {"mesh": entry} if isinstance(entry, str) else entry
        mesh_path = os.path.join(folder, entry["mesh"])
        ext = os.path.splitext(mesh_path)[1].lower()
        up = entry.get("up") or ("Y" if ext in (".glb", ".gltf") else as_written["up"])
        made = _import_level_mesh(mesh_path, up, as_written.get("meters_per_unit", 1.0),
                                  scene_io.meters_per_bu(scene))
        for obj in made:
            for c in list(obj.users_collection):
                c.objects.unlink(obj)
            level_coll.objects.link(obj)
            obj.probeproxy.level_index = index
        context.view_layer.update()
        depsgraph = context.evaluated_depsgraph_get()
        for obj in made:
            if obj.type == "MESH":
                obj.probeproxy.level_fingerprint = scene_io.fingerprint(obj, depsgraph)
    for order, d in enumerate(world["probes"]):
        obj = bpy.data.objects.get(d["name"])
        if obj is None or not obj.probeproxy.is_probe:
            obj = bpy.data.objects.new(d["name"], None)
            obj.empty_display_type = "PLAIN_AXES"
            obj.empty_display_size = 0.25
            probe_coll.objects.link(obj)
        scene_io.set_probe_from_dict(obj, d, scene_io.meters_per_bu(scene))
        obj.probeproxy.order = order
    settings.scene_file = path
    settings.file_up = as_written["up"]
    settings.meters_per_unit = as_written.get("meters_per_unit", 1.0)
    settings.level_json = json.dumps(as_written["level"])
    settings.measured_with_json = json.dumps(world.get("measured_with", {}))
    settings.findings.clear()
    settings.validated = False
    return len(world["probes"])


class PROBEPROXY_OT_import_scene(_NeedsModule, bpy.types.Operator, _OpensJson):
    """Read a probeproxy scene file (*.scene.json): the level meshes and the probes"""
    bl_idname = "probeproxy.import_scene"
    bl_label = "Import Scene"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        def work():
            count = import_scene(context, self.filepath)
            self.report({"INFO"}, "imported %d probes from %s" % (count, self.filepath))
            return {"FINISHED"}

        return _run(self, work)


class PROBEPROXY_OT_save_scene(_NeedsModule, bpy.types.Operator, ExportHelper):
    """Write the probes (and the level's mesh files) as a probeproxy scene file, the one the
    command line reads"""
    bl_idname = "probeproxy.save_scene"
    bl_label = "Save Scene"
    bl_options = {"REGISTER"}

    filename_ext = ".json"
    filter_glob: StringProperty(default="*.json", options={"HIDDEN"})

    def invoke(self, context, event):
        if context.scene.probeproxy.scene_file:
            self.filepath = bpy.path.abspath(context.scene.probeproxy.scene_file)
        return ExportHelper.invoke(self, context, event)

    def execute(self, context):
        scene = context.scene
        settings = scene.probeproxy
        path = os.path.abspath(self.filepath)

        def work():
            _take_edited_proxies(self, context)
            data = scene_io.scene_dict(scene)
            anchor = scene_io.scene_anchor(scene)
            authored_here = not json.loads(settings.level_json or "[]")
            if authored_here:
                # Blender's glTF exporter writes Blender units: the file's unit is the Unit
                # Scale from now on. An imported level keeps its file's unit.
                settings.meters_per_unit = scene_io.meters_per_bu(scene)
                # A level authored in Blender: written beside the scene file, glTF (+Y up).
                level_file = os.path.splitext(os.path.splitext(path)[0])[0] + "_level.glb"
                objects = [o for o in scene.objects if scene_io.is_level_object(o)]
                for o in context.view_layer.objects:
                    o.select_set(o in objects)
                bpy.ops.export_scene.gltf(filepath=level_file, export_format="GLB",
                                          use_selection=True, export_apply=True)
                data["level"] = [{"mesh": os.path.basename(level_file)}]
                anchor = path
            native.module.write_scene(data, path, anchor=anchor, up=settings.file_up,
                                      meters_per_unit=scene_io.f32(settings.meters_per_unit))
            settings.level_json = json.dumps(native.module.read_scene(path)["level"])
            settings.scene_file = path
            self.report({"INFO"}, "wrote " + path)
            return {"FINISHED"}

        return _run(self, work)


def _take_eevee_presets(operator, context, export, source):
    """Makes the Reflection Cubemaps of a proxies.json's EEVEE presets, seeing as far as the
    level is large, and says how many, and which probes got none (no closed proxy to fit a
    parallax box to)."""
    scene = context.scene
    k = scene_io.meters_per_bu(scene)
    presets = eevee_probes.presets_in_export(export)
    made = eevee_probes.make_light_probes(
        scene, presets, k, eevee_probes.level_size_m(_level_objects(context), k))
    missing = [p["name"] for p in export["probes"] if p["name"] not in presets]
    text = "%d EEVEE Reflection Cubemap%s from %s (collection \"%s\")" % (
        len(made), "" if len(made) == 1 else "s", source, eevee_probes.COLLECTION)
    if missing:
        operator.report({"WARNING"}, text + "; none for " + ", ".join(missing) +
                        ": no closed proxy (see proxies.json)")
    else:
        operator.report({"INFO"}, text)
    return {"FINISHED"}


class PROBEPROXY_OT_eevee_probes(_NeedsModule, _LibraryJob, bpy.types.Operator):
    """Turn the scene's probes into EEVEE Reflection Cubemaps that render as probeproxy measured
    them: the EEVEE preset the export writes for each probe (influence, falloff, custom
    parallax box), in the "EEVEE Probes" collection, ready to bake"""
    bl_idname = "probeproxy.eevee_probes"
    bl_label = "EEVEE Probes"
    bl_options = {"REGISTER", "UNDO"}

    def steps(self, context):
        scene = context.scene
        built = _build_input(self, context)
        if built is None:
            return {"CANCELLED"}
        parts, used, scene_data, anchor, options = built
        # The export's own bytes, so that the light probes are exactly what it would write.
        with tempfile.TemporaryDirectory(prefix="probeproxy-eevee-") as out:
            yield lambda progress: native.module.export_proxies(
                scene_data, anchor, out, parts, options, progress)
            with open(os.path.join(out, "proxies.json")) as f:
                export = json.load(f)
        scene.probeproxy.level_used = used
        return _take_eevee_presets(self, context, export, "the scene's probes")


class PROBEPROXY_OT_eevee_probes_from_file(_NeedsModule, bpy.types.Operator, _OpensJson):
    """EEVEE Reflection Cubemaps from a proxies.json that `probeproxy build` or `probeproxy
    layout --engine eevee` wrote"""
    bl_idname = "probeproxy.eevee_probes_from_file"
    bl_label = "EEVEE Probes from File"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        def work():
            path = os.path.abspath(self.filepath)
            try:
                with open(path) as f:
                    export = json.load(f)
            except OSError as e:
                raise native.module.InputError("%s: cannot open: %s" % (path, e.strerror))
            except ValueError as e:
                raise native.module.InputError("%s: not JSON: %s" % (path, e))
            if not isinstance(export, dict) or "probeproxy_runtime" not in export:
                raise native.module.InputError(
                    "%s: not a probeproxy proxies.json (no \"probeproxy_runtime\")" % path)
            return _take_eevee_presets(self, context, export, os.path.basename(path))

        return _run(self, work)


class PROBEPROXY_OT_add_probe(bpy.types.Operator):
    """Add a reflection probe at the 3D cursor"""
    bl_idname = "probeproxy.add_probe"
    bl_label = "Add Probe"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        # A room-sized probe in metres, whatever the scene's Unit Scale: the properties' defaults
        # are Blender units, 2 cm in a centimetre scene.
        per_metre = 1.0 / scene_io.meters_per_bu(context.scene)
        obj = bpy.data.objects.new("probe", None)
        obj.empty_display_type = "PLAIN_AXES"
        obj.empty_display_size = 0.25 * per_metre
        obj.location = context.scene.cursor.location
        s = obj.probeproxy
        for name in ("half_extents", "inner_half_extents", "proxy_half_extents"):
            setattr(s, name, tuple(2.0 * per_metre for _ in range(3)))
        for name in ("radius", "inner_radius", "proxy_radius"):
            setattr(s, name, 2.0 * per_metre)
        obj.rotation_mode = "QUATERNION"
        obj.probeproxy.is_probe = True
        obj.probeproxy.order = 1 + max((p.probeproxy.order for p in scene_io.probes(context.scene)),
                                       default=-1)
        scene_io.collection(context.scene, "Probes").objects.link(obj)
        for o in context.view_layer.objects:
            o.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        return {"FINISHED"}


classes = (PROBEPROXY_OT_generate_proxies, PROBEPROXY_OT_validate_volumes,
           PROBEPROXY_OT_suggest_probes,
           PROBEPROXY_OT_export_proxies, PROBEPROXY_OT_eevee_probes,
           PROBEPROXY_OT_eevee_probes_from_file, PROBEPROXY_OT_import_scene,
           PROBEPROXY_OT_save_scene, PROBEPROXY_OT_add_probe)


register, unregister = bpy.utils.register_classes_factory(classes)

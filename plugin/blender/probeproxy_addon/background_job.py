# Long operators run the library off Blender's main thread, as Blender's own bakes do: the
# interface stays live, the progress bar and the status bar follow the library's reports, and
# Esc stops the job at its next report, with nothing written or changed.
#
# Such an operator writes its work as `steps(context)`, a generator that checks and gathers on
# the main thread, yields the one library call (a function of a progress callback), receives
# its result and applies it on the main thread. `ModalJob` runs the steps modal when invoked
# from a window, on the spot from a script or in the background (`blender -b`).

import threading

import bpy


class Cancelled(Exception):
    """Raised from the progress callback: the library stops the job at its next report."""


class LibraryCall:
    """One library call on a worker thread: its latest (done, total) and its outcome. Nothing
    here touches Blender's data: only the steps on the main thread do."""

    def __init__(self, call):
        self.done, self.total = 0, 0
        self.cancel = False
        self.result, self.error = None, None
        self._thread = threading.Thread(target=self._run, args=(call,), daemon=True)
        self._thread.start()

    def _progress(self, done, total):
        if self.cancel:
            raise Cancelled()
        self.done, self.total = done, total

    def _run(self, call):
        try:
            self.result = call(self._progress)
        except BaseException as e:  # noqa: BLE001: handed to the main thread's steps
            self.error = e

    def finished(self):
        return not self._thread.is_alive()


def _rest(steps, send):
    """Runs the steps on from where they yielded; returns what they return."""
    try:
        send()
    except StopIteration as done:
        return done.value
    raise RuntimeError("an operator's steps yield one library call")


class ModalJob:
    """Mixin for an operator with `steps(context)`; `run_guarded(operator, work)` (the
    operators' one-line error reporting) and `with_progress(context, call)` are given by the
    subclass's module as class attributes."""

    def execute(self, context):
        if getattr(self, "_modal_wanted", False) and context.window is not None:
            return self._start_modal(context)

        def work():
            steps = self.steps(context)
            try:
                call = next(steps)
            except StopIteration as done:
                return done.value
            result = type(self).with_progress(context, call)
            return _rest(steps, lambda: steps.send(result))
        return type(self).run_guarded(self, work)

    def invoke(self, context, event):
        if context.window is None:
            return self.execute(context)
        return self._start_modal(context)

    def _start_modal(self, context):
        self._steps = self.steps(context)
        begun = {}

        def begin():
            try:
                begun["call"] = next(self._steps)
            except StopIteration as done:
                return done.value
            return {"RUNNING_MODAL"}
        started = type(self).run_guarded(self, begin)
        if started != {"RUNNING_MODAL"}:
            return started
        self._job = LibraryCall(begun["call"])
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.progress_begin(0, 1000)
        wm.modal_handler_add(self)
        self._status(context)
        return {"RUNNING_MODAL"}

    def _status(self, context):
        job = self._job
        done = " %d of %d," % (job.done, job.total) if job.total else ""
        text = "%s:%s %s" % (self.bl_label, done,
                             "cancelling" if job.cancel else "Esc to cancel")
        context.workspace.status_text_set(text)
        context.window_manager.progress_update(int(1000 * job.done / max(job.total, 1)))

    def modal(self, context, event):
        if event.type == "ESC" and event.value == "PRESS":
            self._job.cancel = True
            self._status(context)
            return {"RUNNING_MODAL"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        self._status(context)
        if not self._job.finished():
            return {"RUNNING_MODAL"}
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)
        job = self._job
        if isinstance(job.error, Cancelled):
            self.report({"WARNING"}, "%s cancelled: nothing changed" % self.bl_label)
            return {"CANCELLED"}
        if job.error is not None:
            return type(self).run_guarded(
                self, lambda: _rest(self._steps, lambda: self._steps.throw(job.error)))
        return type(self).run_guarded(
            self, lambda: _rest(self._steps, lambda: self._steps.send(job.result)))

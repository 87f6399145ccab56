// probeproxy_py: the library's jobs for Python (the Blender add-on), in plain data. Scenes are
// dicts shaped as the scene file (docs/cli_and_formats.md "Scene file"), reports are the CLI's
// `--json` reports as dicts, meshes are lists of tuples. Bad input raises probeproxy_py.InputError
// (a ValueError) with the library's message, which names the file and the problem. Long work runs
// with the GIL released; progress is reported on the calling thread.

#include "core/errors/input_error.h"
#include "geometry/engines/engine.h"
#include "geometry/engines/engine_reflection.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/export/runtime_export.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/scene/scene_file.h"
#include "geometry/survey/survey_map.h"
#include "plugin/jobs/build/build_job.h"
#include "plugin/jobs/build/build_report.h"
#include "plugin/jobs/layout/layout_job.h"
#include "plugin/jobs/layout/layout_worker.h"
#include "plugin/jobs/scene_input.h"
#include "plugin/jobs/validate/validate_job.h"
#include "plugin/jobs/validate/validate_report.h"
#include "plugin/python/python_level.h"
#include "plugin/python/python_options.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>

namespace py = pybind11;

namespace probeproxy::python {

namespace {

py::object jsonLoads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

std::string jsonDumps(const py::object& value) {
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

UpAxis upAxis(const std::string& up) {
  if (up == "Y") return UpAxis::Y;
  if (up == "Z") return UpAxis::Z;
  throw py::value_error("up must be \"Y\" or \"Z\", got \"" + up + "\"");
}

// The dict as the scene file it spells, read through the file reader's full validation.
// `anchor` is the file the dict stands for: relative paths resolve against its folder and
// errors name it. `up` / `metersPerUnit` change the frame a later write uses, not the values.
Scene sceneFromDict(const py::dict& scene, const std::string& anchor,
                    const std::optional<std::string>& up,
                    const std::optional<double>& metersPerUnit) {
  Scene parsed = parseSceneFile(jsonDumps(scene), std::filesystem::absolute(anchor));
  if (up) parsed.fileUp = upAxis(*up);
  if (metersPerUnit) {
    if (!(*metersPerUnit > 0.0)) throw py::value_error("meters_per_unit must be positive");
    parsed.metersPerUnit = *metersPerUnit;
  }
  return parsed;
}

py::dict sceneDict(Scene scene, bool worldFrame) {
  if (worldFrame) {  // Blender's frame: the values as the Scene holds them
    scene.fileUp = UpAxis::Z;
    scene.metersPerUnit = 1.0;
  }
  return jsonLoads(sceneFileJson(scene));
}

using Progress = jobs::Progress;

// Runs `work` on a worker thread with the GIL released and calls `progress(done, total)` on
// this thread as the work reports it (Blender's progress bar may only be touched from the
// main thread). Exceptions of either side come out here, after the worker has finished; a
// `progress` that raises stops the work at its next report (that is how the add-on cancels),
// and its exception comes out.
template <typename Result>
Result runWithProgress(const std::function<Result(const Progress&)>& work,
                       const py::object& progress) {
  std::mutex mutex;
  std::condition_variable wake;
  std::optional<std::pair<std::size_t, std::size_t>> pending;
  bool finished = false;
  std::optional<Result> result;
  std::exception_ptr workError;
  std::optional<py::error_already_set> callbackError;
  std::atomic<bool> stop{false};
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result = work([&](std::size_t done, std::size_t total) {
          if (stop) throw jobs::JobCancelled();
          const std::lock_guard<std::mutex> lock(mutex);
          pending = {done, total};
          wake.notify_one();
        });
      } catch (...) {
        workError = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      finished = true;
      wake.notify_one();
    });
    for (;;) {
      std::unique_lock<std::mutex> lock(mutex);
      wake.wait(lock, [&] { return pending.has_value() || finished; });
      const auto report = pending;
      pending.reset();
      const bool last = finished;
      lock.unlock();
      if (report && !progress.is_none() && !callbackError) {
        py::gil_scoped_acquire acquire;
        try {
          progress(report->first, report->second);
        } catch (py::error_already_set& e) {
          callbackError.emplace(std::move(e));
          stop = true;
        }
      }
      if (last) break;
    }
    worker.join();
  }
  if (callbackError) throw std::move(*callbackError);
  if (workError) std::rethrow_exception(workError);
  return std::move(*result);
}

// The job's input: the dict's scene and the level parts of `level` (None: the scene's own
// meshes, as the CLI loads them).
jobs::SceneInput sceneInput(const py::dict& sceneData, const std::string& anchor,
                            const py::object& level) {
  jobs::SceneInput input;
  input.scene = sceneFromDict(sceneData, anchor, std::nullopt, std::nullopt);
  if (!level.is_none()) input.level = levelSources(*input.scene, level.cast<py::list>());
  return input;
}

using Triple = std::array<double, 3>;

glm::dvec3 vec(const Triple& t) { return {t[0], t[1], t[2]}; }

py::object tripleOrNone(const std::optional<glm::dvec3>& v) {
  if (!v) return py::none();
  return py::make_tuple(v->x, v->y, v->z);
}

// For each shaded point (with its normal and the camera that sees it): where its mirror
// reflection really lands and what `engine` shows there from the presets of `proxies`
// (geometry/engines/engine_reflection.h), on the level of the scene file `scene`.
py::dict engineReflections(const std::string& scenePath, const std::string& proxiesPath,
                           const std::string& engineName, const std::vector<Triple>& points,
                           const std::vector<Triple>& normals, const std::vector<Triple>& eyes) {
  if (normals.size() != points.size() || eyes.size() != points.size())
    throw py::value_error("points, normals and eyes must have the same length");
  const Engine engine = parseEngine(engineName, "engine");
  std::vector<ReflectionSample> samples(points.size());
  std::vector<EngineReflection> shown(points.size());
  {
    py::gil_scoped_release release;
    jobs::SceneInput input;
    input.file = scenePath;
    const Scene scene = jobs::readSceneInput(input);
    const LevelRayCaster level(jobs::loadSceneLevel(scene, input));
    const EngineModel model = engineModel(engine, readRuntimeExport(proxiesPath), BlendOptions{});
    tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
      ReflectionSample& s = samples[i];
      s.xMeters = vec(points[i]);
      s.normal = glm::normalize(vec(normals[i]));
      s.eyeMeters = vec(eyes[i]);
      s.reflected = glm::reflect(glm::normalize(s.xMeters - s.eyeMeters), s.normal);
      traceTrueHit(level, s);
      shown[i] = engineReflection(level, model, s);
    });
  }
  py::list trueHits, shownPoints, surfaceWeights, skyWeights, fallbackWeights, texels;
  for (std::size_t i = 0; i < points.size(); ++i) {
    trueHits.append(samples[i].hitsSky ? py::none() : tripleOrNone(samples[i].trueHitMeters));
    shownPoints.append(tripleOrNone(shown[i].shownMeters));
    surfaceWeights.append(shown[i].surfaceWeight);
    skyWeights.append(shown[i].skyWeight);
    fallbackWeights.append(shown[i].fallbackWeight);
    py::list pixel;
    for (const ShownTexel& t : shown[i].texels)
      pixel.append(py::make_tuple(t.weight, t.pointMeters.x, t.pointMeters.y, t.pointMeters.z));
    texels.append(pixel);
  }
  py::dict out;
  out["true_hit"] = trueHits;
  out["shown"] = shownPoints;
  out["surface_weight"] = surfaceWeights;
  out["sky_weight"] = skyWeights;
  out["fallback_weight"] = fallbackWeights;
  out["texels"] = texels;
  return out;
}

// The level of the scene file `scene` as the library loads it: (vertices, triangles), world
// metres, Z up: what a renderer must draw for its pixels to be compared with the library's rays.
py::tuple levelTriangles(const std::string& scenePath) {
  jobs::SceneInput input;
  input.file = scenePath;
  LevelMesh level;
  {
    py::gil_scoped_release release;
    level = jobs::loadSceneLevel(jobs::readSceneInput(input), input);
  }
  py::list vertices, triangles;
  for (const glm::vec3& v : level.positionsMeters) vertices.append(py::make_tuple(v.x, v.y, v.z));
  for (const glm::uvec3& t : level.triangles) triangles.append(py::make_tuple(t.x, t.y, t.z));
  return py::make_tuple(vertices, triangles);
}

// The survey maps' degree scale: [(lower edge in degrees, (r, g, b)), ...], bins in order.
py::list surveyScale() {
  py::list bins;
  for (double edge : kSurveyScaleDeg) {
    const auto rgb = surveyErrorColour(edge);
    bins.append(py::make_tuple(edge, py::make_tuple(rgb[0], rgb[1], rgb[2])));
  }
  return bins;
}

// The build job on the dict's scene; writes proxies.json + proxies.glb into `outFolder` when
// it is given.
jobs::BuildJobResult buildScene(const py::dict& sceneData, const std::string& anchor,
                                const py::object& level, const py::dict& options,
                                const py::object& progress,
                                const std::optional<std::string>& outFolder) {
  jobs::BuildJobOptions job;
  job.input = sceneInput(sceneData, anchor, level);
  readBuildOptions(options, job);
  if (outFolder) job.outFolder = *outFolder;
  return runWithProgress<jobs::BuildJobResult>(
      [&](const Progress& onProbeDone) { return jobs::runBuildJob(job, onProbeDone); }, progress);
}

// `probeproxy validate --json`'s findings as dicts: the same report text, parsed, so every
// value is the CLI's to the bit (a value that is not finite is None, as it is null there).
py::list validateFindings(const py::dict& sceneData, const std::string& anchor,
                          const py::object& level, const py::dict& options) {
  jobs::ValidateJobOptions job;
  job.input = sceneInput(sceneData, anchor, level);
  readValidateOptions(options, job);
  std::string report;
  {
    py::gil_scoped_release release;
    report = jobs::validateReportJson(jobs::runValidateJob(job).findings);
  }
  return jsonLoads(report)["findings"];
}

py::tuple vec3(const glm::dvec3& v) { return py::make_tuple(v.x, v.y, v.z); }

// The CLI's `build --json` probes, each with what Blender draws: the kept proxy's planes and
// boundary mesh in world metres (the runtime export's, so a sphere is its icosphere) and the
// build's findings.
py::list probeResults(const Scene& scene, const std::vector<ProbeProxyBuild>& builds) {
  py::list probes = jsonLoads(jobs::buildReportJson(builds))["probes"];
  const RuntimeExport runtime = makeRuntimeExport(scene, builds);
  for (std::size_t i = 0; i < builds.size(); ++i) {
    py::dict probe = probes[i].cast<py::dict>();
    const RuntimeProbe& r = runtime.probes[i];
    py::list planes, vertices, triangles;
    for (const ProxyPlane& p : r.convex.planes)
      planes.append(py::make_tuple(p.normal.x, p.normal.y, p.normal.z, p.offsetMeters));
    for (const glm::dvec3& v : r.convex.verticesMeters) vertices.append(vec3(v));
    for (const glm::uvec3& t : r.convex.triangles) triangles.append(py::make_tuple(t.x, t.y, t.z));
    probe["capture"] = vec3(r.captureMeters);
    probe["plane_equations"] = planes;
    probe["mesh"] = py::dict(py::arg("vertices") = vertices, py::arg("triangles") = triangles,
                             py::arg("display_only") = r.meshIsDisplayOnly);
    probe["findings"] = py::cast(builds[i].findings);
  }
  return probes;
}

// `probeproxy layout` on the dict's scene (its probes seed the floor where the level has no
// spawn points), writing what the CLI writes into `outFolder`. Returns {"scene": the layout's
// scene dict in the world frame, "probes": its probes' build results as build_proxies gives
// them, "figures": layout.json, "files": the paths written}.
py::dict suggestProbes(const py::dict& sceneData, const std::string& anchor,
                       const std::string& outFolder, const py::object& level,
                       const py::dict& options, const py::object& progress) {
  jobs::LayoutJobOptions job;
  job.input = sceneInput(sceneData, anchor, level);
  job.outFolder = outFolder;
  readLayoutOptions(options, job);
  const jobs::LayoutJobResult r = runWithProgress<jobs::LayoutJobResult>(
      [&](const Progress& onStep) { return jobs::runLayoutJob(job, onStep); }, progress);
  py::list files;
  for (const std::filesystem::path& file : r.written) files.append(file.string());
  return py::dict(py::arg("scene") = sceneDict(r.scene, true),
                  py::arg("probes") = probeResults(r.scene, r.builds),
                  py::arg("figures") = jsonLoads(r.json), py::arg("files") = files);
}

// A layout job of a scene or level file, with the module's layout options.
jobs::LayoutJobOptions fileLayoutJob(const std::string& levelOrScene, const py::dict& options) {
  jobs::LayoutJobOptions job;
  job.levelOrScene = levelOrScene;
  readLayoutOptions(options, job);
  return job;
}

// The bytes `work` makes, made with the GIL released (a Dask worker's other threads run).
template <class Work>
py::bytes bytesWithoutGil(Work&& work) {
  std::string made;
  {
    py::gil_scoped_release release;
    made = work();
  }
  return py::bytes(made);
}

// A Python callable for the job's thread: called with the GIL held, its arguments converted
// from `In` and its answer, a list of bytes, to strings. Copies of the job's options outlive no
// call but may be dropped on the job's thread: the last reference goes with the GIL held too.
template <class In>
std::function<std::vector<std::string>(const In&)> bytesFromPython(const py::object& callable) {
  const std::shared_ptr<py::object> held(new py::object(callable), [](py::object* c) {
    py::gil_scoped_acquire acquire;
    delete c;
  });
  return [held](const In& in) {
    py::gil_scoped_acquire acquire;
    py::object arg;
    if constexpr (std::is_same_v<In, std::vector<std::string>>) {
      py::list items;
      for (const std::string& item : in) items.append(py::bytes(item));
      arg = items;
    } else {
      arg = py::cast(in);
    }
    std::vector<std::string> out;
    for (const py::handle bytes : (*held)(arg)) out.push_back(bytes.cast<std::string>());
    return out;
  };
}

// `probeproxy layout LEVEL_OR_SCENE --out DIR` with the candidate stage's tiles judged by
// `judgeTiles(tiles) -> [bytes]` and the final proxies built by `buildProxies(tasks) -> [bytes]`
// (scripts/layout_dask.py: a Dask cluster), else here.
py::dict layoutLevel(const std::string& levelOrScene, const std::string& outFolder,
                     const py::dict& options, const py::object& judgeTiles,
                     const py::object& buildProxies, const py::object& progress) {
  jobs::LayoutJobOptions job = fileLayoutJob(levelOrScene, options);
  job.outFolder = outFolder;
  if (!judgeTiles.is_none())
    job.layout.judgeTiles = bytesFromPython<std::vector<std::vector<std::size_t>>>(judgeTiles);
  if (!buildProxies.is_none())
    job.buildProxies = bytesFromPython<std::vector<std::string>>(buildProxies);
  const jobs::LayoutJobResult r = runWithProgress<jobs::LayoutJobResult>(
      [&](const Progress& onStep) { return jobs::runLayoutJob(job, onStep); }, progress);
  py::list files;
  for (const std::filesystem::path& file : r.written) files.append(file.string());
  return py::dict(py::arg("figures") = jsonLoads(r.json), py::arg("files") = files);
}

}  // namespace

}  // namespace probeproxy::python

PYBIND11_MODULE(probeproxy_py, m) {
  using namespace probeproxy;
  using namespace probeproxy::python;
  m.doc() = "probeproxy: convex proxies for parallax-corrected cubemaps (plain-data interface)";
  m.attr("python_version") = py::str(PY_VERSION);  // the Python this module was built for
  m.attr("__version__") = "0.1.0";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  m.def(
      "read_scene",
      [](const std::string& path, bool worldFrame) {
        Scene scene;
        {
          py::gil_scoped_release release;
          scene = readSceneFile(path);
        }
        return sceneDict(std::move(scene), worldFrame);
      },
      py::arg("path"), py::arg("world_frame") = false,
      "Reads and validates a scene file. Returns it as a dict in its canonical form; with "
      "world_frame the numbers are Z up, metres (Blender's frame) and up/meters_per_unit say so.");

  m.def(
      "scene_json",
      [](const py::dict& scene, const std::string& anchor, std::optional<std::string> up,
         std::optional<double> metersPerUnit) {
        return sceneFileJson(sceneFromDict(scene, anchor, up, metersPerUnit));
      },
      py::arg("scene"), py::arg("anchor"), py::arg("up") = py::none(),
      py::arg("meters_per_unit") = py::none(),
      "The canonical scene file bytes of a scene dict, validated as a file is. `anchor`: the "
      "file the dict stands for (relative paths resolve against its folder); `up` and "
      "`meters_per_unit`: the frame to write in (the dict's own by default).");

  m.def(
      "write_scene",
      [](const py::dict& scene, const std::string& path, std::optional<std::string> anchor,
         std::optional<std::string> up, std::optional<double> metersPerUnit) {
        const Scene parsed = sceneFromDict(scene, anchor.value_or(path), up, metersPerUnit);
        py::gil_scoped_release release;
        writeSceneFile(parsed, path);
      },
      py::arg("scene"), py::arg("path"), py::arg("anchor") = py::none(), py::arg("up") = py::none(),
      py::arg("meters_per_unit") = py::none(),
      "Writes a scene dict to `path` atomically (relative paths are rewritten for the new "
      "folder). Nothing is written if it does not validate.");

  m.def(
      "build_proxies",
      [](const py::dict& scene, const std::string& anchor, const py::object& level,
         const py::dict& options, const py::object& progress) {
        const jobs::BuildJobResult built =
            buildScene(scene, anchor, level, options, progress, std::nullopt);
        return probeResults(built.scene, built.builds);
      },
      py::arg("scene"), py::arg("anchor"), py::arg("level") = py::none(),
      py::arg("options") = py::dict(), py::arg("progress") = py::none(),
      "Builds every probe's proxy. level: None for the scene's own meshes, or a list of parts "
      "({'scene_level': i} or {'name', 'vertices', 'triangles'} in world metres). options: "
      "tolerance_deg, max_planes, max_miss_rate, face_size, samples, regenerate, threads. "
      "progress(done, total) is called as probes finish. Returns the `build --json` probes, "
      "each with capture, plane_equations, mesh {vertices, triangles, display_only}, findings.");

  m.def("validate_scene", &validateFindings, py::arg("scene"), py::arg("anchor"),
        py::arg("level") = py::none(), py::arg("options") = py::dict(),
        "Validates the probes' volumes against the level (`probeproxy validate`). level: as "
        "build_proxies. options (the CLI's, same defaults): tolerance_deg, max_overlap, "
        "max_uncovered_m2, max_leak_share, max_inner_overlap_m3, max_weight_jump, glossy, "
        "grid, samples, rules (a list of rule ids: only those are measured); and threads. Returns "
        "the findings of `validate --json`, in its order: "
        "dicts with probe, rule, severity, value, limit (None where not finite), message, "
        "hint. An empty list: the scene is clean.");

  m.def(
      "export_proxies",
      [](const py::dict& scene, const std::string& anchor, const std::string& outFolder,
         const py::object& level, const py::dict& options, const py::object& progress) {
        const jobs::BuildJobResult built =
            buildScene(scene, anchor, level, options, progress, outFolder);
        return probeResults(built.scene, built.builds);
      },
      py::arg("scene"), py::arg("anchor"), py::arg("out_dir"), py::arg("level") = py::none(),
      py::arg("options") = py::dict(), py::arg("progress") = py::none(),
      "build_proxies, then writes out_dir/proxies.json and proxies.glb (the bytes `probeproxy "
      "build SCENE --out DIR` writes for the same scene, level and options).");

  m.def("engine_reflections", &engineReflections, py::arg("scene"), py::arg("proxies"),
        py::arg("engine"), py::arg("points"), py::arg("normals"), py::arg("eyes"),
        "For each shaded point (world metres, Z up), with its surface normal and the eye that "
        "sees it: {true_hit: where its mirror reflection lands (None: the sky), shown: the "
        "weight-averaged level point the engine's probe lookups show there (None: none meets a "
        "surface), surface_weight, sky_weight, fallback_weight, texels: [(weight, x, y, z) of each "
        "weighted lookup that meets a surface]}, each a list. scene: a scene "
        "file (its level); proxies: a proxies.json; engine: as `survey --engine`.");
  m.def("level_triangles", &levelTriangles, py::arg("scene"),
        "The level of a scene file as the library loads it: (vertices, triangles), world "
        "metres, Z up.");
  m.def("survey_scale", &surveyScale,
        "The survey maps' colour scale: [(lower edge in degrees, (r, g, b)), ...].");
  m.def("layout_level", &layoutLevel, py::arg("level_or_scene"), py::arg("out_dir"),
        py::arg("options") = py::dict(), py::arg("judge_tiles") = py::none(),
        py::arg("build_proxies") = py::none(), py::arg("progress") = py::none(),
        "`probeproxy layout LEVEL_OR_SCENE --out DIR`: a scene file or a level file laid out, "
        "the same files written. options: as suggest_probes, and tile_size (m: the candidate "
        "stage a square tile of the floor at a time). judge_tiles: None (the tiles are judged "
        "here), or a callable given each tile's capture point indices (a list of lists) that "
        "returns, for each tile in order, the bytes LayoutWorker.judge gives for it, from "
        "wherever it ran (scripts/layout_dask.py). build_proxies: None (the laid-out probes' "
        "final proxies are built here), or a callable given each probe's packed task (a list of "
        "bytes) that returns, in order, the bytes LayoutWorker.build_proxy gives for each. "
        "Returns {figures (layout.json), files}.");
  py::class_<jobs::LayoutWorker>(
      m, "LayoutWorker",
      "One process's share of a layout: the level read, its floor walked and its capture "
      "points laid as layout_level does for the same level and options, once; then the "
      "candidates of any capture points and the final proxy of any probe.")
      .def(py::init([](const std::string& levelOrScene, const py::dict& options) {
             const jobs::LayoutJobOptions job = fileLayoutJob(levelOrScene, options);
             py::gil_scoped_release release;
             return std::make_unique<jobs::LayoutWorker>(job);
           }),
           py::arg("level_or_scene"), py::arg("options") = py::dict())
      .def_property_readonly("capture_points", &jobs::LayoutWorker::capturePoints,
                             "how many capture points the layout judges")
      .def(
          "judge",
          [](const jobs::LayoutWorker& worker, const std::vector<std::size_t>& captures) {
            return bytesWithoutGil([&] { return worker.judge(captures); });
          },
          py::arg("captures"),
          "The candidates of these capture points (indices), packed: their sight and the floor "
          "samples each fit region's proxy serves (geometry/layout/candidate_wire.h).")
      .def(
          "build_proxy",
          [](const jobs::LayoutWorker& worker, const py::bytes& task) {
            const std::string taskBytes = task;
            return bytesWithoutGil([&] { return worker.buildProxy(taskBytes); });
          },
          py::arg("task"),
          "The final proxy of one laid-out probe, from its packed task (layout_level hands "
          "them to build_proxies), packed: every candidate tried and the one kept "
          "(geometry/layout/proxy_build_wire.h).");
  m.def(
      "suggest_probes", &suggestProbes, py::arg("scene"), py::arg("anchor"), py::arg("out_dir"),
      py::arg("level") = py::none(), py::arg("options") = py::dict(),
      py::arg("progress") = py::none(),
      "Lays out probes for the whole level (`probeproxy layout`): the fewest that serve its "
      "walkable floor within the tolerance, their influence boxes and proxies. The floor is "
      "the part players reach from the level's spawn points, else from the scene's probes. "
      "Writes into out_dir what `probeproxy layout SCENE --out DIR` writes (layout.scene.json, "
      "proxies, layout.json, the error maps). level: as build_proxies. options: tolerance_deg, "
      "max_probes, spacing, max_candidates, reach, capture_height, blend_band, tile_size, threads. "
      "Returns {scene (world frame), probes (as build_proxies), figures, files}.");
}

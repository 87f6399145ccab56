#include "plugin/python/python_level.h"

#include "core/errors/input_error.h"
#include "geometry/level/load_level.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace py = pybind11;

namespace probeproxy::python {

namespace {

template <typename T, typename Stored>
void copyAs(const py::buffer_info& info, std::vector<T>& out) {
  const auto* data = static_cast<const Stored*>(info.ptr);
  out.assign(data, data + info.size);
}

// Any contiguous buffer (array.array, memoryview, numpy) or plain sequence of numbers.
// Blender hands mesh data out fastest through foreach_get into an array.array.
template <typename T>
std::vector<T> numbers(const py::handle& object, const std::string& what) {
  std::vector<T> out;
  if (!PyObject_CheckBuffer(object.ptr())) {
    for (py::handle item : py::reinterpret_borrow<py::sequence>(object))
      out.push_back(item.cast<T>());
    return out;
  }
  const py::buffer_info info = py::reinterpret_borrow<py::buffer>(object).request();
  std::string format = info.format;
  while (!format.empty() && (format[0] == '@' || format[0] == '=' || format[0] == '<'))
    format.erase(0, 1);
  const char code = format.size() == 1 ? format[0] : '?';
  const bool isFloat = code == 'f' || code == 'd';
  const bool isSigned = code == 'b' || code == 'h' || code == 'i' || code == 'l' || code == 'q';
  const bool isUnsigned = code == 'B' || code == 'H' || code == 'I' || code == 'L' || code == 'Q';
  if (isFloat && info.itemsize == 4)
    copyAs<T, float>(info, out);
  else if (isFloat && info.itemsize == 8)
    copyAs<T, double>(info, out);
  else if (isSigned && info.itemsize == 4)
    copyAs<T, std::int32_t>(info, out);
  else if (isSigned && info.itemsize == 8)
    copyAs<T, std::int64_t>(info, out);
  else if (isUnsigned && info.itemsize == 4)
    copyAs<T, std::uint32_t>(info, out);
  else
    throw py::type_error(what + ": unsupported buffer format '" + info.format + "'");
  return out;
}

LevelMesh meshPart(const Scene& scene, const py::dict& part, std::size_t index) {
  const std::string where = "level part " + std::to_string(index);
  const std::string name = part.contains("name") ? part["name"].cast<std::string>() : where;
  if (!part.contains("vertices") || !part.contains("triangles"))
    throw InputError(scene.file,
                     where + " (" + name + "): expected \"vertices\" and \"triangles\"");
  const std::vector<double> xyz = numbers<double>(part["vertices"], where + " vertices");
  const std::vector<long long> corners =
      numbers<long long>(part["triangles"], where + " triangles");
  if (xyz.size() % 3 != 0 || corners.size() % 3 != 0)
    throw InputError(scene.file,
                     where + " (" + name + "): vertices and triangles must hold 3 numbers each");
  LevelMesh mesh;
  mesh.positionsMeters.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    if (!std::isfinite(xyz[i]) || !std::isfinite(xyz[i + 1]) || !std::isfinite(xyz[i + 2]))
      throw InputError(scene.file, where + " (" + name + "): vertex " + std::to_string(i / 3) +
                                       " is not finite");
    mesh.positionsMeters.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  }
  const long long vertexCount = static_cast<long long>(mesh.positionsMeters.size());
  for (std::size_t i = 0; i < corners.size(); i += 3) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (corners[i + c] < 0 || corners[i + c] >= vertexCount)
        throw InputError(scene.file, where + " (" + name + "): triangle " + std::to_string(i / 3) +
                                         " names vertex " + std::to_string(corners[i + c]) +
                                         " of " + std::to_string(vertexCount));
    }
    mesh.triangles.emplace_back(corners[i], corners[i + 1], corners[i + 2]);
  }
  mesh.parts.push_back({name, {}, 0, static_cast<std::uint32_t>(mesh.triangles.size())});
  return mesh;
}

}  // namespace

std::vector<LevelSource> levelSources(const Scene& scene, const py::list& parts) {
  std::vector<LevelSource> sources;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const py::dict part = parts[i].cast<py::dict>();
    if (!part.contains("scene_level")) {
      sources.emplace_back(meshPart(scene, part, i));
      continue;
    }
    const long long index = part["scene_level"].cast<long long>();
    if (index < 0 || index >= static_cast<long long>(scene.level.size())) {
      throw InputError(scene.file, "level part " + std::to_string(i) +
                                       ": the scene has no level mesh " + std::to_string(index));
    }
    sources.emplace_back(static_cast<std::size_t>(index));
  }
  return sources;
}

LevelMesh loadLevelSources(const Scene& scene, const std::vector<LevelSource>& sources) {
  LevelMesh level;
  for (const LevelSource& source : sources) {
    if (const auto* index = std::get_if<std::size_t>(&source)) {
      const LevelMeshRef& ref = scene.level[*index];
      appendLevelMesh(level, loadLevelMeshFile(ref.path, ref.up, scene.metersPerUnit));
    } else {
      appendLevelMesh(level, std::get<LevelMesh>(source));
    }
  }
  if (level.triangles.empty()) throw InputError(scene.file, "the level has no triangles");
  return level;
}

}  // namespace probeproxy::python

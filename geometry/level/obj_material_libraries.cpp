#include "geometry/level/obj_material_libraries.h"

#include "core/io/regular_file.h"

#include <fstream>
#include <sstream>
#include <string>

namespace probeproxy {

void requireReadableMaterialLibraries(const std::filesystem::path& obj) {
  std::ifstream in(obj, std::ios::binary);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) || keyword != "mtllib") continue;
    for (std::string name; words >> name;) {
      const std::filesystem::path library = obj.parent_path() / name;
      std::error_code ec;
      if (std::filesystem::exists(library, ec)) requireRegularFile(library, "OBJ material library");
    }
  }
}

}  // namespace probeproxy

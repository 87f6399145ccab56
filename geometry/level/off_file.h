#pragma once
// OFF level meshes (Geomview's Object File Format), read here. CGAL 5.5's OFF scanner, which
// read them before, trusts the file: fuzzing found it casting a negative index or corner count
// to size_t and reading a COFF vertex's colour past the end of a short line (a heap overflow).
// ASCII OFF with the optional ST, C and N prefixes; a vertex's extras (normal, colour, texture
// coordinates) and a face's colour are ignored. Binary, 4D (4OFF) and n-dimensional (nOFF)
// files are refused by name. '#' starts a comment.

#include "geometry/level/polygon_soup.h"

#include <filesystem>

namespace probeproxy {

// The points and faces as written; every face index checked against the vertex count. Throws
// InputError(file, "malformed mesh: ...") naming the problem: "not a complete off file (header,
// counts or data)", "face 0 refers to vertex -2 of 8", "the file claims 2147483648 corners in a
// face, more than its 45 bytes can hold", ...
PolygonSoup readOffFile(const std::filesystem::path& file);

}  // namespace probeproxy

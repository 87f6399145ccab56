#pragma once
// What a PLY file claims, checked against the bytes it holds before CGAL's reader sees it.
// CGAL 5.5's PLY reader trusts the file: it sizes each list property's buffer from the
// count written before the list, so a 150-byte file whose one face claims 2^31 corners took
// 8.5 GB and half a minute before it failed; and it adds a property to the last element seen
// without checking there is one (a property before any element line: back() on an empty
// vector); a vertex coordinate of an integer type leaves it a null pointer to read through; a
// header without end_header it reads as complete, then takes counts from a stream at
// its end. This walks the header and the data once, allocating nothing, and names the first
// claim the file cannot back.

#include <filesystem>
#include <string>

namespace probeproxy {

// Empty when every list fits in what is left of the file and the header declares each property
// under an element; otherwise the problem, e.g. "PLY element face 0: a list of 2147483648
// items, past the end of the file", or "not a complete ply file (header, counts or data)" for
// data cut short (as CGAL's own failure reads).
std::string plyClaimProblem(const std::filesystem::path& file);

}  // namespace probeproxy

#include "geometry/level/ply_claims.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace probeproxy {

namespace {

enum class Encoding { Ascii, LittleEndian, BigEndian };

// The line a cut file gets, the same CGAL's failure gives (polygon_soup_file.cpp).
constexpr const char* kIncomplete = "not a complete ply file (header, counts or data)";

struct Property {
  int size = 0;              // bytes of a scalar, or of each list item
  int countSize = 0;         // bytes of a list's count; 0 for a scalar
  bool countSigned = false;  // CGAL casts a negative count to size_t: 2^64 - n items
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

// Bytes of a PLY scalar type, 0 for a type CGAL's reader does not know (it then ignores the
// property, and so must this walk, or the two would read different bytes as a list's count).
int typeSize(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// A list's count type: the integer types only, as CGAL takes them.
int countTypeSize(const std::string& type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64"
             ? 0
             : typeSize(type);
}

// A binary count, as the reader will take it: unsigned, in the file's byte order.
std::uint64_t binaryCount(const char* at, int size, Encoding encoding) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    const int byte = encoding == Encoding::LittleEndian ? size - 1 - i : i;
    value = (value << 8) | static_cast<unsigned char>(at[byte]);
  }
  return value;
}

// An ASCII instance is one line (the PLY standard's layout, and what CGAL's reader takes):
// exactly the values its properties declare, a list's count first. A line short of a value
// would shift every later value into the wrong property. Blank lines are skipped. Moves `at`
// past the line.
std::string asciiInstanceProblem(const std::string& bytes, std::size_t& at, const Element& element,
                                 std::uint64_t index) {
  std::string line;
  while (at < bytes.size() && line.find_first_not_of(" \t\r") == std::string::npos) {
    std::size_t lineEnd = bytes.find('\n', at);
    if (lineEnd == std::string::npos) lineEnd = bytes.size();
    line = bytes.substr(at, lineEnd - at);
    at = lineEnd + 1;
  }
  if (line.find_first_not_of(" \t\r") == std::string::npos) return kIncomplete;
  std::istringstream words(line);
  std::vector<std::string> values{std::istream_iterator<std::string>(words), {}};
  const std::string where = "PLY element " + element.name + " " + std::to_string(index);
  const auto miscount = [&](const char* fewerOrMore) {
    return where + ": its line holds " + std::to_string(values.size()) + " values, " + fewerOrMore +
           " than its properties declare (one element to a line)";
  };
  std::size_t next = 0;
  for (const Property& property : element.properties) {
    if (next >= values.size()) return miscount("fewer");
    if (property.countSize == 0) {
      ++next;
      continue;
    }
    char* rest = nullptr;
    const std::uint64_t items = std::strtoull(values[next].c_str(), &rest, 10);
    if (values[next][0] == '-' || *rest != '\0')
      return where + ": list count '" + values[next] + "' is not a count";
    if (items > values.size() - next - 1) {
      return where + ": a list of " + std::to_string(items) + " items, past the end of its line";
    }
    next += 1 + items;
  }
  if (next != values.size()) return miscount("more");
  return {};
}

}  // namespace

std::string plyClaimProblem(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  std::size_t body = std::string::npos;
  // The header line by line, as CGAL's getline reads it; only each line is copied.
  for (std::size_t start = 0, lineNumber = 1; start < bytes.size(); ++lineNumber) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos) end = bytes.size();
    std::istringstream words(bytes.substr(start, end - start));
    start = end + 1;
    std::string keyword, type;
    words >> keyword;
    if (keyword == "end_header") {
      body = std::min(start, bytes.size());
      break;
    }
    // The format comes from the second line only, as CGAL reads it (and the standard places
    // it); a later format line is ignored by both.
    if (lineNumber == 2) {
      words >> type;
      encoding = type == "binary_little_endian" ? Encoding::LittleEndian
                 : type == "binary_big_endian"  ? Encoding::BigEndian
                                                : Encoding::Ascii;
    } else if (keyword == "element") {
      Element element;
      words >> element.name >> element.count;
      elements.push_back(element);
    } else if (keyword == "property") {
      if (elements.empty()) {
        return "PLY header line " + std::to_string(lineNumber) +
               " declares a property before any element";
      }
      Property property;
      std::string name;
      words >> type;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType >> name;
        property.countSize = countTypeSize(countType);
        property.countSigned = countType == "char" || countType == "int8" || countType == "short" ||
                               countType == "int16" || countType == "int" || countType == "int32";
        property.size = property.countSize > 0 ? typeSize(itemType) : 0;
      } else {
        words >> name;
        property.size = typeSize(type);
      }
      // CGAL reads a vertex's x, y, z as float or double whatever the header says: another
      // type leaves it a null pointer to read through (found by fuzz_level_ply).
      const std::string& element = elements.back().name;
      const bool coordinate = name == "x" || name == "y" || name == "z";
      const bool floating =
          type == "float" || type == "float32" || type == "double" || type == "float64";
      if ((element == "vertex" || element == "vertices") && coordinate && property.size > 0 &&
          !floating) {
        return "PLY header line " + std::to_string(lineNumber) + ": vertex coordinate " + name +
               " is " + type + ", expected float or double";
      }
      if (property.size > 0) elements.back().properties.push_back(property);
    }
  }
  // CGAL's reader takes a header that never ends as a whole one and then reads counts from a
  // stream at its end (found by fuzz_level_ply: 9.5 GB asked for); every PLY has the line.
  if (body == std::string::npos) return "PLY header has no end_header line";

  // The data: skip each value; at each list, the count must fit in what is left.
  std::size_t at = body;
  const std::size_t end = bytes.size();

  for (const Element& element : elements) {
    // Every instance takes a byte at the least; one of no property (every one of a type CGAL
    // ignores) takes none, but CGAL still loops over as many as the header claims (found by
    // fuzz_level_ply: 2.4 * 10^12 of them).
    if (element.count > end - body) {
      return "PLY element " + element.name + " claims " + std::to_string(element.count) +
             " instances, more than the file's " + std::to_string(end - body) +
             " bytes of data hold";
    }
    if (element.properties.empty()) continue;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      if (encoding == Encoding::Ascii) {
        if (std::string p = asciiInstanceProblem(bytes, at, element, i); !p.empty()) return p;
        continue;
      }
      for (const Property& property : element.properties) {
        // Data cut short: CGAL would go on reading counts from a stream at its end (found by
        // fuzz_level_ply: a count of garbage, then a loop as long as it says).
        if (at + std::max(property.countSize, property.size) > end) return kIncomplete;
        if (property.countSize == 0) {
          at += property.size;
          continue;
        }
        const std::uint64_t items = binaryCount(bytes.data() + at, property.countSize, encoding);
        if (property.countSigned && (items >> (8 * property.countSize - 1)) != 0) {
          return "PLY element " + element.name + " " + std::to_string(i) +
                 ": a list of a negative number of items";
        }
        at += property.countSize;
        if (items > (end - at) / std::uint64_t(property.size)) {
          return "PLY element " + element.name + " " + std::to_string(i) + ": a list of " +
                 std::to_string(items) + " items, past the end of the file";
        }
        at += items * std::uint64_t(property.size);
      }
    }
  }
  return {};
}

}  // namespace probeproxy

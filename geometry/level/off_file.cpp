#include "geometry/level/off_file.h"

#include "core/errors/input_error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

namespace {

// The file's non-empty lines, comments cut, each split at whitespace; one line at a time.
class OffLines {
 public:
  explicit OffLines(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    text_.assign(std::istreambuf_iterator<char>(in), {});
  }
  // False at the end of the file.
  bool next(std::vector<std::string_view>& words) {
    words.clear();
    while (words.empty() && at_ < text_.size()) {
      std::size_t end = text_.find('\n', at_);
      if (end == std::string::npos) end = text_.size();
      std::string_view line(text_.data() + at_, end - at_);
      at_ = end + 1;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
      }
    }
    return !words.empty();
  }
  std::size_t bytesLeft() const { return at_ < text_.size() ? text_.size() - at_ : 0; }
  std::size_t bytes() const { return text_.size(); }

 private:
  std::string text_;
  std::size_t at_ = 0;
};

// A whole word as a number; a leading '+' is taken, as the stream readers OFF files were
// written for take it (from_chars does not).
template <typename T>
bool parse(std::string_view word, T& value) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size();
}

}  // namespace

PolygonSoup readOffFile(const std::filesystem::path& file) {
  const auto fail = [&](const std::string& problem) -> InputError {
    return InputError(file, "malformed mesh: " + problem);
  };
  const auto incomplete = [&] { return fail("not a complete off file (header, counts or data)"); };
  OffLines lines(file);
  std::vector<std::string_view> words;
  if (!lines.next(words)) throw incomplete();

  // The keyword, [ST][C][N][4][n]OFF, optional; the counts may follow it on its line.
  std::size_t first = 0;
  static const std::regex keyword("(ST)?C?N?(4)?(n)?OFF");
  std::cmatch m;
  if (std::regex_match(words[0].data(), words[0].data() + words[0].size(), m, keyword)) {
    if (m[2].matched || m[3].matched)
      throw fail(std::string(words[0]) +
                 " (4D or n-dimensional) is not read: save the level as 3D OFF or PLY");
    if (words.size() > 1 && words[1] == "BINARY")
      throw fail("binary OFF is not read: save the level as ASCII OFF or PLY");
    first = 1;  // the counts on the keyword's line, or
    if (words.size() == 1) {
      if (!lines.next(words)) throw incomplete();
      first = 0;  // on the next
    }
  }
  long long vertexCount = -1, faceCount = -1;
  if (words.size() < first + 2 || !parse(words[first], vertexCount) ||
      !parse(words[first + 1], faceCount) || vertexCount < 0 || faceCount < 0)
    throw incomplete();

  PolygonSoup soup;
  // Reserve no more than the file can hold (a vertex line is 6 bytes at the least): a count
  // is a claim, not a size.
  soup.points.reserve(std::min<std::size_t>(std::size_t(vertexCount), lines.bytes() / 6));
  for (long long v = 0; v < vertexCount; ++v) {
    glm::dvec3 p;
    if (!lines.next(words) || words.size() < 3 || !parse(words[0], p.x) || !parse(words[1], p.y) ||
        !parse(words[2], p.z))
      throw incomplete();
    soup.points.push_back(p);
  }
  for (long long f = 0; f < faceCount; ++f) {
    long long corners = 0;
    if (!lines.next(words) || !parse(words[0], corners)) throw incomplete();
    if (corners < 0)
      throw fail("face " + std::to_string(f) + " has " + std::to_string(corners) + " corners");
    if (std::size_t(corners) > lines.bytes() / 2) {
      throw fail("the file claims " + std::to_string(corners) +
                 " corners in a face, more than its " + std::to_string(lines.bytes()) +
                 " bytes can hold");
    }
    if (words.size() < std::size_t(corners) + 1) throw incomplete();
    for (long long k = 1; k <= corners; ++k) {
      long long index = 0;
      if (!parse(words[std::size_t(k)], index)) throw incomplete();
      if (index < 0 || index >= vertexCount) {
        throw fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                   " of " + std::to_string(vertexCount));
      }
      soup.corners.push_back(std::size_t(index));
    }
    soup.faceEnds.push_back(soup.corners.size());
  }
  return soup;
}

}  // namespace probeproxy

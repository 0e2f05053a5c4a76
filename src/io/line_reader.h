// line_reader.h - the strict line-oriented reading that the project's text input files share (terrain profiles and
// grids, terrain/terrain_file.cpp; source tracks, io/source_track.cpp).
//
// Every problem throws SceneError (so the program exits with code 2) with a message
//   <file>:<line>: expected <what>, got <found>
// and input is bounded before it is stored: a line longer than kMaxLineLength characters is refused.
#pragma once

#include <cstddef>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_reader.h"

namespace cdmpm::text {

inline constexpr std::size_t kMaxLineLength = std::size_t(1) << 24;  // characters per line (16 MiB)

using Tokens = std::vector<std::string_view>;

// A number as a message shows it (12 significant digits).
std::string fmt(double v);
// A token as shown in a message: quoted, cut at 40 characters.
std::string shown(std::string_view t);
// Throws SceneError "<path>:<line>: expected <what>, got <got>" (no line when line <= 0).
[[noreturn]] void fail(const std::string& path, int line, const std::string& what, const std::string& got);

// Reads a file line by line, counting lines and refusing lines longer than kMaxLineLength. `kind` names the file in
// the messages of a file that cannot be opened ("terrain file": "<path>: cannot open terrain file (no such file)").
class LineReader {
 public:
  LineReader(const std::string& path, const std::string& kind);
  // The next line without its end of line ('\n' or "\r\n"); false at the end of the file.
  bool next(std::string& line);
  int line() const { return line_ > 1 ? line_ : 1; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ifstream in_;
  int line_ = 0;
};

std::string_view trim(std::string_view s);
Tokens split_whitespace(std::string_view s);
Tokens split_commas(std::string_view s);
// The whole token as a number (a leading '+' allowed); false if it is not one. NaN and inf parse.
bool parse_number(std::string_view t, double& v);
// A finite number, or an error at the reader's current line; `what` reads "a number (distance)".
double finite_number(const LineReader& in, std::string_view t, const std::string& what);

}  // namespace cdmpm::text

#include "shared/mesh/off_check.hpp"

#include <climits>

#include "shared/mesh/text_tokenizer.hpp"

namespace altfem {

void check_off_text(std::string_view text, const std::string& file_name) {
  TextTokenizer tokens(text, file_name, '#');
  if (tokens.at_end()) tokens.fail("empty file, expected an OFF header");
  const std::string_view header = tokens.next("an OFF header");
  if (!header.ends_with("OFF")) tokens.fail_expected("an OFF header such as 'OFF'", header);
  // nOFF and 4OFF change the coordinate count; BINARY is not text.
  if (header.find_first_of("n4") != std::string_view::npos || tokens.peek() == "BINARY") return;
  const long long vertex_count = tokens.next_integer("the number of vertices", 0, INT_MAX);
  const int header_line = tokens.line();
  const long long face_count = tokens.next_integer("the number of faces", 0, INT_MAX);
  tokens.next_integer("the number of edges", 0, LLONG_MAX);
  tokens.skip_rest_of_line();

  const auto truncated = [&](const char* items, long long declared, long long found) {
    tokens.fail("truncated file: the header on line " + std::to_string(header_line) + " declares " +
                std::to_string(declared) + " " + items + ", found " + std::to_string(found));
  };
  for (long long vertex = 0; vertex < vertex_count; ++vertex) {
    if (tokens.at_end()) truncated("vertices", vertex_count, vertex);
    for (const char* axis : {"a vertex x coordinate", "a vertex y coordinate", "a vertex z coordinate"})
      tokens.next_real(axis);
    tokens.skip_rest_of_line();  // optional colour or texture coordinates
  }
  for (long long face = 0; face < face_count; ++face) {
    if (tokens.at_end()) truncated("faces", face_count, face);
    const long long corners = tokens.next_integer("the number of a face's vertices", 3, INT_MAX);
    for (long long corner = 0; corner < corners; ++corner) {
      const long long vertex = tokens.next_integer("a face vertex index", LLONG_MIN, LLONG_MAX);
      if (vertex < 0 || vertex >= vertex_count)
        tokens.fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(vertex) +
                    ", expected 0 to " + std::to_string(vertex_count - 1));
    }
    tokens.skip_rest_of_line();  // optional colour
  }
}

}  // namespace altfem

#pragma once
// A whitespace tokenizer over a whole text file that remembers the line of every
// token, so that each parse error can name "file: line N" (docs/conventions.md, principle 5).
// Written by hand because the file formats are tiny and the errors must carry lines;
// it never reads past the text (the parsers are fuzzed).
#include <string>
#include <string_view>

namespace altfem {

class TextTokenizer {
public:
  /// `comment` starts a comment that runs to the end of the line ('\0': no comments).
  TextTokenizer(std::string_view text, std::string file_name, char comment = '\0');

  /// True when only whitespace and comments remain.
  bool at_end();
  /// The next token without consuming it; empty at the end of the text.
  std::string_view peek();
  /// The next token; `what` names what was expected for the truncation error.
  std::string_view next(std::string_view what);
  /// The next token as an integer in [minimum, maximum].
  long long next_integer(std::string_view what, long long minimum, long long maximum);
  /// The next token as a finite real number (NaN and infinity are errors).
  double next_real(std::string_view what);
  /// Consumes `expected` exactly, else fails.
  void expect(std::string_view expected);
  /// Drops the rest of the current line (e.g. optional colours after OFF coordinates).
  void skip_rest_of_line();

  /// Line (1-based) of the token returned last, or of the end of the text.
  int line() const { return line_; }
  const std::string& file_name() const { return file_name_; }
  /// Throws InputError "file: line N: what".
  [[noreturn]] void fail(const std::string& what) const;
  /// Throws InputError "file: line N: expected <expected>, got '<token>'".
  [[noreturn]] void fail_expected(std::string_view expected, std::string_view got) const;

private:
  void skip_space();

  std::string_view text_;
  std::string file_name_;
  char comment_;
  std::size_t position_ = 0;
  int current_line_ = 1;  // line at position_
  int line_ = 1;
};

/// A token made safe to quote in a one-line message: at most 40 printable characters.
std::string quoted_token(std::string_view token);

}  // namespace altfem

#include "shared/mesh/text_tokenizer.hpp"

#include <charconv>
#include <cmath>

#include "shared/common/error.hpp"

namespace altfem {

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
}  // namespace

std::string quoted_token(std::string_view token) {
  constexpr std::size_t longest = 40;
  std::string quoted = "'";
  for (std::size_t i = 0; i < token.size() && i < longest; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    quoted += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if (token.size() > longest) quoted += "...";
  return quoted + "'";
}

TextTokenizer::TextTokenizer(std::string_view text, std::string file_name, char comment)
    : text_(text), file_name_(std::move(file_name)), comment_(comment) {}

void TextTokenizer::skip_space() {
  while (position_ < text_.size()) {
    const char c = text_[position_];
    if (c == '\n') {
      ++current_line_;
      ++position_;
    } else if (is_space(c)) {
      ++position_;
    } else if (comment_ != '\0' && c == comment_) {
      while (position_ < text_.size() && text_[position_] != '\n') ++position_;
    } else {
      return;
    }
  }
}

bool TextTokenizer::at_end() {
  skip_space();
  return position_ >= text_.size();
}

std::string_view TextTokenizer::peek() {
  skip_space();
  std::size_t end = position_;
  while (end < text_.size() && !is_space(text_[end]) && !(comment_ != '\0' && text_[end] == comment_)) ++end;
  return text_.substr(position_, end - position_);
}

std::string_view TextTokenizer::next(std::string_view what) {
  const std::string_view token = peek();
  // At the end of the text the error names the last line that had a token.
  if (token.empty()) fail("file ends early: expected " + std::string(what));
  line_ = current_line_;
  position_ += token.size();
  return token;
}

long long TextTokenizer::next_integer(std::string_view what, long long minimum, long long maximum) {
  const std::string_view token = next(what);
  long long value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) fail_expected(what, token);
  if (value < minimum || value > maximum)
    fail("expected " + std::string(what) + " in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
         "], got " + std::string(token));
  return value;
}

double TextTokenizer::next_real(std::string_view what) {
  std::string_view token = next(what);
  // from_chars rejects a leading '+', which some writers emit.
  std::string_view digits = token;
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range)
    fail(std::string(what) + " is out of the range of double: " + quoted_token(token));
  if (error != std::errc() || end != digits.data() + digits.size()) fail_expected(what, token);
  if (!std::isfinite(value)) fail(std::string(what) + " is not finite, got " + quoted_token(token));
  return value;
}

void TextTokenizer::expect(std::string_view expected) {
  const std::string_view token = next(expected);
  if (token != expected) fail_expected(expected, token);
}

void TextTokenizer::skip_rest_of_line() {
  while (position_ < text_.size() && text_[position_] != '\n') ++position_;
}

void TextTokenizer::fail(const std::string& what) const {
  throw InputError(input_message(file_name_, "line " + std::to_string(line_), what));
}

void TextTokenizer::fail_expected(std::string_view expected, std::string_view got) const {
  fail("expected " + std::string(expected) + ", got " + quoted_token(got));
}

}  // namespace altfem

#include "pkg/io/TextTokens.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <system_error>

namespace roundedmesh {

std::string shown(std::string_view token) {
  std::string text = "'";
  const std::size_t length = std::min<std::size_t>(token.size(), 24);
  for (std::size_t i = 0; i < length; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      text += char(c);
    } else {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", unsigned(c));
      text += escaped;
    }
  }
  return text + (token.size() > length ? "...'" : "'");
}

Parsed parseReal(std::string_view token, double& value) {
  const char* begin = token.data();
  const char* const end = begin + token.size();
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-' && begin[1] != '+') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value, std::chars_format::general);
  if (error == std::errc::invalid_argument || stop != end) return Parsed::notANumber;
  if (error == std::errc::result_out_of_range) return Parsed::outOfRange;
  return error == std::errc() ? Parsed::number : Parsed::notANumber;
}

}  // namespace roundedmesh

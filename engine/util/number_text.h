// Numbers in messages: the shortest text that reads back as the same value (std::to_chars), so that a limit and a
// value beside it never print alike unless they are equal ("1.0000001e+20 is over the limit of 1e+20", not
// "1e+20 is over the limit of 1e+20"; a range of [1.001, 10], not [1, 10]).
#pragma once

#include <charconv>
#include <string>

namespace raylab {

inline std::string numberText(float value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

inline std::string numberText(double value) {
  char text[40];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace raylab

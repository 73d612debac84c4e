#pragma once
// One error type for everything read from outside (files, network, frames) and for bad
// arguments. The message is a single line a user can act on; programs print it and go on
// serving others (or exit non-zero when the bad input was their own command line).
#include <stdexcept>
#include <string>

namespace inkwire {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(one_line(message)) {}

 private:
  static std::string one_line(std::string s) {
    for (char& c : s)
      if (c == '\n' || c == '\r') c = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
  }
};

}  // namespace inkwire

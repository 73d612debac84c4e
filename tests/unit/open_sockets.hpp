#pragma once
// How many sockets this process holds open now: a unit test of server code that must run without
// the network (the relay's ordering, the call's roster) says so by ending with none.
#include <filesystem>
#include <string>

namespace inkwire::test {

inline int open_sockets() {
  int n = 0;
  std::error_code ec;
  for (const auto& fd : std::filesystem::directory_iterator("/proc/self/fd", ec)) {
    const auto target = std::filesystem::read_symlink(fd.path(), ec);
    if (!ec && target.string().starts_with("socket:")) ++n;
  }
  return n;
}

}  // namespace inkwire::test

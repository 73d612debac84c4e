#include "server/products/mesh_product_process.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "common/error.hpp"
#include "server/products/product_store.hpp"

extern char** environ;

namespace inkwire::server {

namespace fs = std::filesystem;

fs::path mesh_product_helper() {
  std::error_code ec;
  return fs::read_symlink("/proc/self/exe", ec).parent_path() / "inkwire-mesh-product";
}

std::vector<std::string> mesh_product_arguments(const fs::path& data, const ProductSource& source) {
  const MeshProductOptions& o = source.mesh_options;
  return {"--data", data.string(), "--mesh", source.mesh.string(), "--samples", std::to_string(o.samples), "--sphere", std::to_string(o.sphere_level),
          "--size", std::to_string(o.size), "--points", std::to_string(o.points), "--style", o.style, "--up", to_string(o.up)};
}

void make_mesh_product_in_helper(const fs::path& data, const ProductSource& source, const PairProgress& progress) {
  const fs::path helper = mesh_product_helper();
  if (!fs::exists(helper)) throw Error("mesh products are made by " + helper.string() + ", which is missing (build it beside this program)");
  std::vector<std::string> args = mesh_product_arguments(data, source);
  args.insert(args.begin(), helper.string());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int out[2];
  if (pipe(out) != 0) throw Error(std::string("cannot start the mesh helper: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDERR_FILENO);  // its reason, when it fails, is the last line
  // The helper takes none of the server's descriptors (the pipe's ends included): a client's
  // socket held by it would outlive the client's leaving.
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, helper.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  if (spawned != 0) {
    close(out[0]);
    throw Error("cannot start " + helper.string() + ": " + std::strerror(spawned));
  }
  // Its lines as add-product prints them: "pair D/T TEXT" per pair, "note: TEXT" per note.
  FILE* lines = fdopen(out[0], "r");
  std::string last;
  char buffer[1024];
  while (lines && std::fgets(buffer, sizeof buffer, lines)) {
    std::string line(buffer);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    if (line.empty()) continue;
    last = line;
    int done = 0, total = 0, used = 0;
    if (std::sscanf(line.c_str(), "pair %d/%d %n", &done, &total, &used) == 2 && used > 0) {
      if (progress) progress(done, total, line.substr(size_t(used)));
    } else if (line.rfind("note: ", 0) == 0) {
      if (progress) progress(0, 0, line.substr(6));
    }
  }
  if (lines) std::fclose(lines);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) throw Error("the mesh helper died of signal " + std::to_string(WTERMSIG(status)) + " making " + source.mesh.string());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw Error(last.empty() ? "the mesh helper failed on " + source.mesh.string() : last);
}

}  // namespace inkwire::server

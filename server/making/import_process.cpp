#include "server/making/import_process.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cstring>

#include <asio/experimental/as_tuple.hpp>
#include <nlohmann/json.hpp>

extern char** environ;

namespace inkwire::server {
namespace {

namespace fs = std::filesystem;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

}  // namespace

fs::path model_importer() {
  std::error_code ec;
  return fs::read_symlink("/proc/self/exe", ec).parent_path() / "inkwire-import-model";
}

asio::awaitable<ImportOutcome> import_model(fs::path folder, fs::path out, const MakingOptions& options) {
  ImportOutcome outcome;
  const fs::path helper = model_importer();
  if (!fs::exists(helper)) {
    outcome.error = "this server cannot import models: " + helper.filename().string() + " is missing beside it";
    co_return outcome;
  }
  std::vector<std::string> args = {helper.string(), "--folder", folder.string(), "--out", out.string(),
                                    "--max-triangles", std::to_string(options.max_triangles), "--max-texture-pixels", std::to_string(options.max_texture_pixels),
                                    "--seconds", std::to_string(options.import_seconds), "--memory-bytes", std::to_string(options.import_memory_bytes)};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_ends[2];
  if (pipe2(pipe_ends, O_CLOEXEC) != 0) {
    outcome.error = std::string("cannot start the importer: ") + std::strerror(errno);
    co_return outcome;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  // None of the server's descriptors (clients' sockets) go with it.
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, helper.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  if (spawned != 0) {
    close(pipe_ends[0]);
    outcome.error = "cannot start the importer: " + std::string(std::strerror(spawned));
    co_return outcome;
  }
  const auto executor = co_await asio::this_coro::executor;
  asio::posix::stream_descriptor output(executor, pipe_ends[0]);
  // Past its time (and a little for starting), the importer is killed: its pipe then ends.
  auto killed = std::make_shared<bool>(false);
  asio::steady_timer deadline(executor, std::chrono::milliseconds(int64_t(options.import_seconds * 1000) + 2000));
  deadline.async_wait([pid, killed](std::error_code ec) {
    if (ec) return;
    *killed = true;
    kill(pid, SIGKILL);
  });
  std::string text;
  for (;;) {
    char buffer[4096];
    auto [ec, n] = co_await output.async_read_some(asio::buffer(buffer), no_throw);
    if (n > 0 && text.size() < 64 * 1024) text.append(buffer, n);
    if (ec) break;
  }
  deadline.cancel();
  // Its output ended: it has exited, or is about to.
  int status = 0;
  for (int tries = 0; waitpid(pid, &status, tries < 200 ? WNOHANG : 0) == 0; ++tries) {
    asio::steady_timer pause(executor, std::chrono::milliseconds(10));
    co_await pause.async_wait(no_throw);
    if (tries == 199) kill(pid, SIGKILL);
  }
  if (*killed) {
    outcome.error = "the model took longer to import than this server allows (" + std::to_string(int(options.import_seconds)) + " s)";
    co_return outcome;
  }
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    outcome.error = signal == SIGXCPU ? "the model took longer to import than this server allows (" + std::to_string(int(options.import_seconds)) + " s)"
                                      : "the importer failed on this model (signal " + std::to_string(signal) + ")";
    co_return outcome;
  }
  nlohmann::json line;
  try {
    line = nlohmann::json::parse(text.substr(0, text.find('\n')));
  } catch (const nlohmann::json::exception&) {
    outcome.error = "the importer failed on this model";
    co_return outcome;
  }
  if (line.contains("error") || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    outcome.error = line.value("error", std::string("the importer failed on this model"));
    co_return outcome;
  }
  outcome.name = line.value("name", std::string("model.glb"));
  outcome.triangles = line.value("triangles", uint64_t(0));
  outcome.texture_pixels = line.value("texture_pixels", uint64_t(0));
  outcome.bytes = line.value("bytes", uint64_t(0));
  co_return outcome;
}

}  // namespace inkwire::server

// inkwire-server: sessions, assets and control messages for thin clients (CONTRACTS.md).
#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "common/error.hpp"
#include "common/log.hpp"
#include "server/server.hpp"

using namespace inkwire;

int main(int argc, char** argv) {
  std::string listen, data, config_file;
  bool quiet = false;
  CLI::App app{"inkwire-server: serves Inkwire sessions (shared scenes, turntables, conferences) to thin clients"};
  app.add_option("--listen", listen, "HOST:PORT to listen on (default 127.0.0.1:7878; port 0 picks a free one)");
  app.add_option("--data", data, "data folder: asset files and the SQLite catalogue (default ./inkwire-data)");
  app.add_option("--config", config_file, "JSON config: listen, data, name, queue_bytes, sessions (see README)");
  app.add_flag("--quiet", quiet, "log warnings and errors only");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (quiet) set_log_level(LogLevel::Warn);
    server::ServerConfig config = config_file.empty() ? server::ServerConfig::embedded_default() : server::ServerConfig::load(config_file);
    if (!listen.empty()) server::parse_listen(listen, config);
    if (!data.empty()) config.data_dir = data;
    // A client vanishing mid-write must not kill the server.
    std::signal(SIGPIPE, SIG_IGN);
    asio::io_context io(1);
    server::Server server(io, config);
    asio::signal_set signals(io, SIGINT, SIGTERM);
    signals.async_wait([&](std::error_code, int signal) {
      log_info("signal", {{"signal", signal}});
      server.stop();
    });
    server.start();
    io.run();
    log_info("stopped");
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "inkwire-server: " << e.what() << "\n";
    return 1;
  }
}

// --suite net, across instances (SPEC D1): the same load as the single-instance rows, with two
// server instances sharing their sessions through a real redis-server, senders on the first and
// receivers on both (the second's deliveries cross the broker); and the peer rows: the same
// fan-out through the broker alone, subscribers on its own protocol, for Redis and for NATS, so
// the server's figures and the two brokers' stand side by side from one run.
#include <hiredis/hiredis.h>
#include <nats/nats.h>

#include <cstdio>
#include <future>
#include <mutex>
#include <thread>

#include <asio.hpp>
#include <asio/experimental/as_tuple.hpp>

#include "bench_harness.hpp"
#include "net_load.hpp"
#include "protocol/framing.hpp"
#include "server/relay/redis_connection.hpp"
#include "server/relay/relay.hpp"
#include "server/server.hpp"

namespace inkwire::bench {
namespace {

using namespace protocol;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

std::string session_name(int i) { return "s" + std::to_string(i); }

// The pose every sender sends, as the server would forward it: the peers carry the same bytes.
Bytes pose_frame(uint32_t sequence) {
  return encode(CameraPose{.sequence = sequence, .position = {0, 1, 10}, .target = {0, 0, 0}, .up = {0, 1, 0}, .fov_y_degrees = 45});
}

// Receivers of a peer row: thread-safe (NATS calls back on its own threads).
struct Deliveries {
  explicit Deliveries(int receivers) : last(size_t(receivers)) {}
  std::mutex mutex;
  std::vector<double> latencies_ms;
  std::vector<Clock::time_point> last;  // per receiver
  int64_t stalls = 0;
  void record(const Load& load, int session, size_t receiver, const uint8_t* frame, size_t size) {
    uint32_t sequence = 0;
    try {
      sequence = std::get<CameraPose>(decode_frame(frame, size)).sequence;
    } catch (const std::exception&) {
      return;
    }
    const auto now = Clock::now();
    std::lock_guard lock(mutex);
    if (sequence >= load.sent[size_t(session)].size()) return;
    latencies_ms.push_back(std::chrono::duration<double, std::milli>(now - load.sent[size_t(session)][sequence]).count());
    if (last[receiver] != Clock::time_point{} && now - last[receiver] > std::chrono::microseconds(3 * 1000000 / load.shape.hz)) ++stalls;
    last[receiver] = now;
  }
};

// Sends one pose per session at R Hz, spread over the period, through `publish`.
void publish_poses(Load& load, std::mutex& sent_mutex, const std::function<void(int session, const Bytes& frame)>& publish) {
  const auto period = std::chrono::microseconds(1000000 / load.shape.hz);
  const auto start = Clock::now();
  struct Due {
    Clock::time_point at;
    int session;
    uint32_t sequence;
  };
  std::vector<Due> due;
  for (int s = 0; s < load.shape.sessions; ++s) due.push_back({start + period + period * s / load.shape.sessions, s, 0});
  const size_t count = load.sent[0].size();
  for (;;) {
    auto next = std::min_element(due.begin(), due.end(), [](const Due& a, const Due& b) { return a.at < b.at; });
    if (next->sequence >= count) break;
    std::this_thread::sleep_until(next->at);
    const Bytes frame = pose_frame(next->sequence);
    {
      std::lock_guard lock(sent_mutex);  // receivers read it on other threads
      load.sent[size_t(next->session)][next->sequence] = Clock::now();
    }
    publish(next->session, frame);
    ++next->sequence;
    next->at += period;
    if (next->sequence >= count) next->at = Clock::time_point::max();
  }
}

Result peer_result(const LoadShape& shape, const std::string& peer, Deliveries& d, double seconds, double broker_cpu, double clients_cpu) {
  Result r;
  r.suite = "net", r.renderer = "net", r.object = "-";
  r.variant = "peer=" + peer + "," + shape.variant();
  Load expected_load(shape, 1);
  const double delivered = double(d.latencies_ms.size());
  r.counters = {{"clients", shape.clients}, {"sessions", shape.sessions}, {"msgs_per_second", delivered / seconds},
                {"delivered_fraction", delivered / expected_load.expected()}, {"p50_ms", percentile(d.latencies_ms, 0.50)},
                {"p99_ms", percentile(d.latencies_ms, 0.99)}, {"max_ms", percentile(d.latencies_ms, 1.0)}, {"stalls", double(d.stalls)},
                {"broker_cpu_fraction", broker_cpu / seconds}, {"clients_cpu_fraction", clients_cpu / seconds},
                {"broker_cpu_us_per_delivery", delivered > 0 ? broker_cpu / delivered * 1e6 : 0}};
  return r;
}

// The broker alone: a publisher per session and a subscriber per receiver, each on its own
// connection, all driven by one Asio thread through the same hiredis code the server uses.
Result redis_peer(const LoadShape& shape) {
  BrokerProcess broker(BrokerProcess::Kind::Redis);
  Load load(shape, 1);
  const int receivers = shape.clients - shape.sessions;
  Deliveries deliveries(receivers);
  asio::io_context io(1);
  std::vector<std::unique_ptr<server::RedisConnection>> publishers, subscribers;
  int subscribed = 0, failed = 0;
  for (int s = 0; s < shape.sessions; ++s) {
    publishers.push_back(std::make_unique<server::RedisConnection>(io));
    publishers.back()->connect("127.0.0.1", uint16_t(broker.port()), std::chrono::seconds(5), [] {}, [&](const std::string&) { ++failed; });
  }
  for (int i = 0; i < receivers; ++i) {
    const int session = i % shape.sessions;
    subscribers.push_back(std::make_unique<server::RedisConnection>(io));
    server::RedisConnection* c = subscribers.back().get();
    c->connect("127.0.0.1", uint16_t(broker.port()), std::chrono::seconds(5),
               [&, c, session, i] {
                 const std::string channel = session_name(session);
                 c->subscribe({channel}, [&, session, i](const redisReply* r) {
                   if (!r || r->type != REDIS_REPLY_ARRAY || r->elements < 3) return;
                   if (std::string_view(r->element[0]->str, r->element[0]->len) == "subscribe") ++subscribed;
                   else deliveries.record(load, session, size_t(i), reinterpret_cast<const uint8_t*>(r->element[2]->str), r->element[2]->len);
                 });
               },
               [&](const std::string&) { ++failed; });
  }
  while (subscribed + failed < receivers) io.run_one();
  const double cpu0 = broker.cpu_seconds(), clients0 = thread_cpu_seconds();
  const auto start = Clock::now();
  // Publishing is paced on this thread; the publish itself goes out from the I/O loop, which
  // this thread runs between poses.
  std::thread pacer([&] {
    publish_poses(load, deliveries.mutex, [&](int session, const Bytes& frame) {
      asio::post(io, [&, session, frame] {
        publishers[size_t(session)]->command({"PUBLISH", session_name(session), std::string_view(reinterpret_cast<const char*>(frame.data()), frame.size())},
                                             [](const redisReply*) {});
      });
    });
  });
  auto work = asio::make_work_guard(io);
  std::thread stopper([&] {
    pacer.join();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the last deliveries
    work.reset();
    asio::post(io, [&] {
      for (auto& c : publishers) c->disconnect();
      for (auto& c : subscribers) c->disconnect();
    });
  });
  io.restart();
  io.run();
  stopper.join();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return peer_result(shape, "redis", deliveries, seconds, broker.cpu_seconds() - cpu0, thread_cpu_seconds() - clients0);
}

// The same through nats-server with the packaged C client (its own threads per connection).
Result nats_peer(const LoadShape& shape) {
  BrokerProcess broker(BrokerProcess::Kind::Nats);
  Load load(shape, 1);
  const int receivers = shape.clients - shape.sessions;
  Deliveries deliveries(receivers);
  const std::string url = "nats://127.0.0.1:" + std::to_string(broker.port());
  natsOptions* options = nullptr;
  natsOptions_Create(&options);
  natsOptions_SetURL(options, url.c_str());
  natsOptions_UseGlobalMessageDelivery(options, true);  // a shared pool, not a thread per subscription
  struct Receiver {
    Deliveries* deliveries;
    Load* load;
    int session;
    size_t index;
  };
  std::vector<Receiver> receiver_info(static_cast<size_t>(receivers));
  std::vector<natsConnection*> connections;
  std::vector<natsSubscription*> subscriptions;
  const double clients0 = thread_cpu_seconds();
  for (int i = 0; i < receivers; ++i) {
    natsConnection* nc = nullptr;
    if (natsConnection_Connect(&nc, options) != NATS_OK) throw Error("cannot connect to nats-server: " + std::string(nats_GetLastError(nullptr)));
    receiver_info[size_t(i)] = {&deliveries, &load, i % shape.sessions, size_t(i)};
    natsSubscription* sub = nullptr;
    natsConnection_Subscribe(&sub, nc, session_name(i % shape.sessions).c_str(),
                             [](natsConnection*, natsSubscription*, natsMsg* msg, void* closure) {
                               auto* r = static_cast<Receiver*>(closure);
                               r->deliveries->record(*r->load, r->session, r->index, reinterpret_cast<const uint8_t*>(natsMsg_GetData(msg)),
                                                     size_t(natsMsg_GetDataLength(msg)));
                               natsMsg_Destroy(msg);
                             },
                             &receiver_info[size_t(i)]);
    connections.push_back(nc), subscriptions.push_back(sub);
  }
  std::vector<natsConnection*> publishers(size_t(shape.sessions));
  for (auto& p : publishers)
    if (natsConnection_Connect(&p, options) != NATS_OK) throw Error("cannot connect to nats-server");
  for (natsConnection* nc : connections) natsConnection_FlushTimeout(nc, 5000);  // every subscription is in place
  const double cpu0 = broker.cpu_seconds();
  const auto start = Clock::now();
  publish_poses(load, deliveries.mutex, [&](int session, const Bytes& frame) {
    natsConnection_Publish(publishers[size_t(session)], session_name(session).c_str(), frame.data(), int(frame.size()));
    natsConnection_FlushTimeout(publishers[size_t(session)], 1000);  // out now, as Redis' PUBLISH is
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count(), broker_cpu = broker.cpu_seconds() - cpu0;
  for (natsSubscription* s : subscriptions) natsSubscription_Destroy(s);
  for (natsConnection* nc : connections) natsConnection_Destroy(nc);
  for (natsConnection* nc : publishers) natsConnection_Destroy(nc);
  natsOptions_Destroy(options);
  return peer_result(shape, "nats", deliveries, seconds, broker_cpu, thread_cpu_seconds() - clients0);
}

// Whether the server's relay is connected, asked on its own I/O thread.
bool relay_connected(server::Server& server, asio::io_context& io) {
  std::promise<bool> answer;
  asio::post(io, [&] { answer.set_value(server.relay().status().connected); });
  return answer.get_future().get();
}

// Two instances on one broker: every session on both; senders on the first, receivers on both.
Result two_instances(const LoadShape& shape, const std::string& data_dir) {
  BrokerProcess broker(BrokerProcess::Kind::Redis);
  const std::string url = "redis://127.0.0.1:" + std::to_string(broker.port());
  struct Instance {
    asio::io_context io{1};
    std::unique_ptr<server::Server> server;
    std::thread thread;
    double cpu_seconds = 0;
  };
  Instance instances[2];
  for (int k = 0; k < 2; ++k) {
    server::ServerConfig config;
    config.port = 0;
    config.data_dir = data_dir + "/" + std::to_string(k);
    config.name = "instance-" + std::to_string(k);
    config.broker = url;
    for (int i = 0; i < shape.sessions; ++i) {
      server::SessionConfig session;
      session.name = session_name(i);
      config.sessions.push_back(std::move(session));
    }
    instances[k].server = std::make_unique<server::Server>(instances[k].io, config);
    instances[k].server->start();
    instances[k].thread = std::thread([&inst = instances[k]] {
      inst.io.run();
      inst.cpu_seconds = thread_cpu_seconds();
    });
  }
  for (int tries = 0; tries < 500 && !(relay_connected(*instances[0].server, instances[0].io) && relay_connected(*instances[1].server, instances[1].io)); ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // resyncs of every session done

  Load load(shape, 2);
  asio::io_context client_io(1);
  std::vector<asio::ip::tcp::endpoint> endpoints;
  for (const Instance& inst : instances) endpoints.push_back({asio::ip::make_address("127.0.0.1"), inst.server->port()});
  for (int i = 0; i < shape.clients; ++i) asio::co_spawn(client_io, simulated_client(endpoints, load, i), asio::detached);
  const auto start = Clock::now();
  const double clients0 = thread_cpu_seconds(), broker0 = broker.cpu_seconds();
  client_io.run();
  const double clients_cpu = thread_cpu_seconds() - clients0, broker_cpu = broker.cpu_seconds() - broker0;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  for (Instance& inst : instances) {
    asio::post(inst.io, [&inst] { inst.server->stop(); });
    inst.thread.join();
  }
  Result r;
  r.suite = "net", r.renderer = "net", r.object = "-";
  r.variant = shape.variant() + ",instances=2";
  const double server_cpu = instances[0].cpu_seconds + instances[1].cpu_seconds;
  r.counters = {{"clients", shape.clients}, {"sessions", shape.sessions}, {"joined", double(load.joined)},
                {"msgs_per_second", double(load.delivered) / seconds}, {"delivered_fraction", double(load.delivered) / load.expected()},
                // Deliveries on the second instance crossed the broker: the figure the target is about.
                {"p50_ms", percentile(load.latencies_ms[1], 0.50)}, {"p99_ms", percentile(load.latencies_ms[1], 0.99)},
                {"max_ms", percentile(load.latencies_ms[1], 1.0)},
                {"same_instance_p50_ms", percentile(load.latencies_ms[0], 0.50)}, {"same_instance_p99_ms", percentile(load.latencies_ms[0], 0.99)},
                {"stalls", double(load.stalls)},
                {"server_cpu_fraction", instances[0].cpu_seconds / seconds}, {"server2_cpu_fraction", instances[1].cpu_seconds / seconds},
                {"broker_cpu_fraction", broker_cpu / seconds}, {"clients_cpu_fraction", clients_cpu / seconds},
                {"server_cpu_us_per_delivery", load.delivered > 0 ? server_cpu / double(load.delivered) * 1e6 : 0},
                {"broker_cpu_us_per_delivery", load.delivered > 0 ? broker_cpu / double(load.delivered) * 1e6 : 0}};
  return r;
}

void print(const Result& r) {
  const auto& c = r.counters;
  std::fprintf(stderr, "  net %s: %.0f msgs/s, p50 %.2f ms, p99 %.2f ms, stalls %.0f, delivered %.3f\n", r.variant.c_str(), c.at("msgs_per_second"),
               c.at("p50_ms"), c.at("p99_ms"), c.at("stalls"), c.at("delivered_fraction"));
}

}  // namespace

std::vector<Result> run_net_instance_rows(const std::string& data_dir) {
  const LoadShape shape{1000, 100, 30, 5};
  std::vector<Result> results;
  try {
    results.push_back(two_instances(shape, data_dir + "/instances"));
    print(results.back());
    results.push_back(redis_peer(shape));
    print(results.back());
    results.push_back(nats_peer(shape));
    print(results.back());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "  net across instances skipped: %s\n", e.what());
  }
  return results;
}

}  // namespace inkwire::bench

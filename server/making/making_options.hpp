#pragma once
// What the operator allows of the sessions people make themselves (SPEC N6-N11): who may open
// call rooms and make scenes from models they bring, how many, how large, and how long an
// unused one lives. Read from the config's "making" object (docs/config.md).
#include <cstddef>
#include <cstdint>
#include <string>

namespace inkwire::server {

// Who may open rooms and make scenes: anyone; whoever gives the creator token (a listener
// others can reach defaults to this); no one (only the operator's config, add-scene and
// add-product make sessions).
enum class MakingPolicy { Anyone, Token, Off };

struct MakingOptions {
  MakingPolicy who = MakingPolicy::Anyone;  // the config's "who": "anyone" | "token" | "off"
  bool who_given = false;                   // false: decided by the listeners (loopback: anyone, else token)
  std::string creator_token;                // for MakingPolicy::Token (kept as its digest once read)
  size_t max_rooms = 1000, max_rooms_per_address = 20;
  size_t max_scenes = 200, max_scenes_per_address = 10;
  double room_idle_seconds = 300;           // a room with no members for this long is gone
  double scene_idle_seconds = 86400;        // an uploaded scene nobody kept, unvisited this long, is gone
  uint64_t max_upload_bytes = 64ull << 20;  // one upload's body
  uint64_t max_triangles = 2'000'000;
  uint64_t max_texture_pixels = 4096ull * 4096;  // all of a model's textures together
  double import_seconds = 30;               // the importer's time, CPU and wall clock
  uint64_t import_memory_bytes = 2ull << 30;  // the importer's address space
  double uploads_per_minute_per_address = 20;  // past it an address waits (429 with Retry-After)
  size_t max_name_length = 64;              // names people give (letters, digits, - _ .)
};

}  // namespace inkwire::server

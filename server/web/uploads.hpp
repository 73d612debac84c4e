#pragma once
// Models people bring (SPEC N8, N10-N11): POST /scenes makes a scene of the model in a multipart
// upload (the front page's "New scene"), POST /scenes/NAME/model replaces a running scene's model
// (its editor only: the key in X-Inkwire-Editor-Key). Refused before a byte of the body is read
// when the policy, the creator token (X-Inkwire-Creator-Token), the caps, the rate per address
// or the size (Content-Length over max_upload_bytes) say no; the body is then written straight
// to files (server/making/multipart.hpp), imported by a process of its own under limits
// (server/making/import_process.hpp), stored as one GLB under its hash, and the folder removed
// whatever happens: nothing half-stored stays. Replies are JSON: {name, page, editor_key,
// triangles, bytes} or {error}.
#include <string>

#include <asio.hpp>

#include "protocol/net/byte_stream.hpp"

namespace inkwire::server {

class Server;
struct Request;

// The reply to an upload; `early` holds body bytes read with the head.
asio::awaitable<std::string> receive_upload(Server& server, ByteStream& socket, const Request& request, const std::string& path, std::string early,
                                            const std::string& address);

}  // namespace inkwire::server

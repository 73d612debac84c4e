#include "server/web/product_files.hpp"

#include "server/server.hpp"
#include "server/web/http_reply.hpp"
#include "server/web/http_request.hpp"

namespace inkwire::server {

std::string product_reply(Server& server, const Request& request, const std::string& path) {
  const std::string rest = path.substr(std::string("/products/").size());
  const size_t slash = rest.find('/');
  const auto session = slash == std::string::npos ? nullptr : server.find_session(rest.substr(0, slash));
  if (!session || session->state().product.directions.empty()) return text_reply(404, "no product " + rest.substr(0, slash), kAnyOrigin);
  const std::shared_ptr<const ProductListing> listing = session->listing();
  if (!listing) return text_reply(503, session->unavailable(), kAnyOrigin);
  const std::string file = rest.substr(slash + 1);
  if (file == "product.json") {
    if (!session->role_of(query_value(request.path, "token")))
      return text_reply(403, "product " + session->name() + " needs its token (?token=)", kAnyOrigin);
    const std::string& tag = listing->etag;
    if (request.header("if-none-match") == tag)
      return "HTTP/1.1 304 Not Modified\r\nETag: " + tag + "\r\nCache-Control: no-cache\r\nConnection: close\r\n" + kAnyOrigin + "\r\n";
    if (request.header("accept-encoding").find("gzip") == std::string::npos)
      return http_reply(200, "application/json", listing->manifest, kAnyOrigin + "ETag: " + tag + "\r\n", "no-cache");
    return http_reply(200, "application/json", listing->manifest_gzipped,
                      kAnyOrigin + "ETag: " + tag + "\r\nContent-Encoding: gzip\r\nVary: Accept-Encoding\r\n", "no-cache");
  }
  const auto found = listing->files.find(file);
  if (found == listing->files.end()) return text_reply(404, "product " + session->name() + " has no file " + file, kAnyOrigin);
  const ProductFile& f = found->second;
  const protocol::Bytes bytes = f.cell ? *f.cell : server.store().read(f.hash, 0, uint32_t(f.size));
  return http_reply(200, f.content_type, std::string(bytes.begin(), bytes.end()), kAnyOrigin, "public, max-age=31536000, immutable");
}

}  // namespace inkwire::server

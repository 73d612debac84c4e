#pragma once
// Every product as a static host serves its export (protocol/PRODUCT.md, deploy/nginx/), at
// /products/NAME/: the manifest revalidated each visit (an ETag answers a repeat visit with
// 304), the files under their hashes kept forever, every reply readable by pages of any origin.
// The manifest of a product with a token is given for the token only (?token=); its files are
// named by hashes nobody can guess without it.
#include <string>

namespace inkwire::server {

class Server;
struct Request;

// The reply to GET /products/NAME/product.json or /products/NAME/files/HEX.ext.
std::string product_reply(Server& server, const Request& request, const std::string& path);

}  // namespace inkwire::server

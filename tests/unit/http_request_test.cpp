// The HTTP listener's reading of what anyone sends (server/web/http_request.hpp): a request head,
// and a value from the target's query (a product's token), percent-decoded or refused.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "server/web/http_request.hpp"
#include "server/web/http_server.hpp"

using namespace inkwire::server;

TEST(HttpRequestTest, AHeadIsReadWithHeaderNamesInLowerCaseAndAHeaderGivenTwiceIsRefused) {
  const Request r = parse_head("GET /products/duck/product.json?token=x HTTP/1.1\r\nHost: a\r\nAccept-Encoding: gzip\r\n\r\n");
  EXPECT_EQ(r.method, "GET");
  EXPECT_EQ(r.path, "/products/duck/product.json?token=x");
  EXPECT_EQ(r.header("accept-encoding"), "gzip");
  EXPECT_THROW(parse_head("GET / HTTP/1.1\r\nHost: a\r\nhost: b\r\n\r\n"), inkwire::Error);
  EXPECT_THROW(parse_head("GET / SPDY/3\r\n\r\n"), inkwire::Error);
}

TEST(HttpRequestTest, AQueryValueIsPercentDecodedAndAMalformedOneIsEmpty) {
  EXPECT_EQ(query_value("/p/product.json?token=sh0p-0wner", "token"), "sh0p-0wner");
  EXPECT_EQ(query_value("/p?a=1&token=a%2Fb%20c+d", "token"), "a/b c d");
  EXPECT_EQ(query_value("/p?tokens=x&token=y", "token"), "y");  // a longer name is another name
  EXPECT_EQ(query_value("/p?token=bad%2", "token"), "");
  EXPECT_EQ(query_value("/p?token=bad%zz", "token"), "");
  EXPECT_EQ(query_value("/p", "token"), "");
  EXPECT_EQ(query_value("/p?token=", "token"), "");
}

// Regression: with allowed_origins naming a shop, the server's own pages were refused their
// WebSocket (its scene page said "closed before it opened").
TEST(HttpRequestTest, TheServersOwnPagesAreAllowedWhateverElseIsAndStarAllowsEveryOrigin) {
  using inkwire::server::origin_allowed;
  const std::vector<std::string> shop = {"https://shop.example"};
  EXPECT_TRUE(origin_allowed("http://127.0.0.1:8080", "127.0.0.1:8080", shop));
  EXPECT_TRUE(origin_allowed("https://shop.example", "127.0.0.1:8080", shop));
  EXPECT_FALSE(origin_allowed("https://evil.example", "127.0.0.1:8080", shop));
  EXPECT_FALSE(origin_allowed("https://evil.example", "127.0.0.1:8080", {}));
  EXPECT_TRUE(origin_allowed("", "127.0.0.1:8080", {})) << "not from a page";
  EXPECT_TRUE(origin_allowed("https://anyone.example", "127.0.0.1:8080", {"*"}));
}

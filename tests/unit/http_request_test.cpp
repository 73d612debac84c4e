// The HTTP listener's reading of what anyone sends (server/web/http_request.hpp): a request head,
// and a value from the target's query (a product's token), percent-decoded or refused.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "server/web/http_request.hpp"

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

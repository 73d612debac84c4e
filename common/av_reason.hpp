#pragma once
// libavcodec's words for one of its error codes, for the messages of the face video's encoder
// (client/call) and decoder (server/call); both link libavutil.
#include <string>

extern "C" {
#include <libavutil/error.h>
}

namespace inkwire {

inline std::string av_reason(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

}  // namespace inkwire

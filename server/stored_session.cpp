#include "server/stored_session.hpp"

#include "common/error.hpp"

namespace inkwire::server {

const char* to_string(MadeBy maker) {
  switch (maker) {
    case MadeBy::Operator: return "operator";
    case MadeBy::Room: return "room";
    case MadeBy::Upload: return "upload";
    case MadeBy::Command: return "add-scene";
  }
  return "operator";
}

MadeBy made_by_from_string(const std::string& name) {
  for (MadeBy m : {MadeBy::Operator, MadeBy::Room, MadeBy::Upload, MadeBy::Command})
    if (name == to_string(m)) return m;
  throw Error("unknown session maker '" + name + "'");
}

}  // namespace inkwire::server

#include "server/web/pages.hpp"

#include <algorithm>
#include <sstream>

#include "server/server.hpp"
#include "server/web/http_reply.hpp"
#include "server/web/http_request.hpp"

namespace inkwire::server {
namespace {

// Presenter mode from a product page's address (/turntable/NAME?present or ?follow): that
// attribute on the page's element. Anything else in the query is left out.
std::string presenter_attribute(const std::string& target) {
  const size_t query = target.find('?');
  if (query == std::string::npos) return "";
  std::istringstream parts(target.substr(query + 1));
  for (std::string part; std::getline(parts, part, '&');)
    if (part == "present" || part == "follow") return " " + part;
  return "";
}

// A session's page: `element` full-size (with `attributes`), and the snippet to paste into one's
// own page. Over TLS the snippet names https:// and wss:// (a shop's https page may load nothing
// else).
std::string element_page(const std::string& element, const std::string& session, const std::string& host, const std::string& invitation, bool tls,
                         const std::string& attributes, const std::string& page_script = "") {
  const std::string http = tls ? "https://" : "http://", ws = tls ? "wss://" : "ws://";
  const std::string snippet = "<script type=\"module\" src=\"" + http + host + "/inkwire.js\"></script>\n<" + element + " server=\"" + ws +
                              host + "/ws\" session=\"" + session + "\" style=\"width: 480px; height: 480px\"></" + element + ">";
  return "<!doctype html><html lang=en><meta charset=utf-8><meta name=viewport content=\"width=device-width, initial-scale=1\">"
         "<title>" + html_escape(session) + "</title><style>html, body { margin: 0; height: 100%; font: 14px system-ui, sans-serif; }"
         " " + element + " { height: calc(100% - 9em); } details { padding: 0.5em 1em; } pre { white-space: pre-wrap; background: #f4f4f4; padding: 0.5em; }"
         "</style>" + (page_script.empty() ? "" : "<link rel=stylesheet href=\"/pages/front.css\"><script type=module src=\"" + page_script + "\"></script>") +
         "<script type=module src=\"/inkwire.js\"></script><" + element + " session=\"" + html_escape(session) + "\"" + attributes + "></" + element +
         "><details><summary>" + invitation + "</summary><pre>" + html_escape(snippet) + "</pre></details>\n";
}

// One family of session pages: its address, the element it shows, which sessions it shows and
// what it calls one it cannot.
struct PageFamily {
  const char* prefix;
  const char* element;
  const char* invitation;
  const char* missing;
  bool (*shows)(Session&);
  const std::string* headers;
};

const std::string kNoHeaders;
const PageFamily kFamilies[] = {
    {"/scene/", "inkwire-scene", "Put this scene on your page", "no scene ",
     [](Session& s) { return s.state().kind == protocol::SessionKind::Scene && s.state().product.directions.empty(); }, &kNoHeaders},
    {"/turntable/", "inkwire-turntable", "Put this product on your page", "no product ",
     [](Session& s) { return !s.state().product.directions.empty(); }, &kNoHeaders},
    {"/conference/", "inkwire-conference", "Put this conference on your page", "no conference ",
     [](Session& s) { return s.state().kind == protocol::SessionKind::Conference; }, &kNoHeaders},
    // The join link of a call: any conference session.
    {"/call/", "inkwire-call", "Put this call on your page", "no call ", [](Session& s) { return s.call() != nullptr; }, &kIsolatedPage},
};

// The page of call room `name` that is not open yet: it opens when its first member joins
// (SPEC N6), who then holds its host key. Where the policy asks for the creator token, the page
// asks for it first.
std::string room_page(Server& server, const Request& request, const std::string& name) {
  const SessionMaker& maker = server.maker();
  const bool needs_token = maker.policy() == MakingPolicy::Token;
  std::string attributes = " open-room";
  if (needs_token) attributes += " token=\"" + html_escape(query_value(request.path, "token")) + "\"";
  std::string page = element_page("inkwire-call", name, request.header("host"), "Put this call on your page", server.tls() != nullptr, attributes);
  if (needs_token && query_value(request.path, "token").empty())
    page += "<form class=creator><label>This server opens rooms for holders of its creator token: <input name=token autocomplete=off></label>"
            " <button>Open the room</button></form>";
  return page;
}

// Under a call's element: the link that brings others in, with a button that copies it.
std::string invite(const std::string& name, const std::string& host, bool tls) {
  const std::string link = std::string(tls ? "https://" : "http://") + host + "/call/" + name;
  return "<p class=invite>Invite others with this link: <a href=\"" + html_escape(link) + "\">" + html_escape(link) +
         "</a> <button onclick=\"navigator.clipboard.writeText(this.previousElementSibling.href).then(() => this.textContent = 'Copied')\">"
         "Copy link</button></p>";
}

}  // namespace

std::optional<std::string> session_page(Server& server, const Request& request, const std::string& path) {
  // "Start a call": a room with an unguessable name (96 random bits), opened when its first member joins.
  if (path == "/call/" || path == "/call") {
    // The creator token goes along, where the form asked for one (percent-encoded as it came).
    const size_t at = request.path.find("token=");
    const std::string token = at == std::string::npos ? "" : request.path.substr(at, request.path.find('&', at) - at);
    return http_reply(303, "text/plain", "", "Location: /call/" + SessionMaker::random_name() + (token.size() > 6 ? "?" + token : "") + "\r\n");
  }
  for (const PageFamily& family : kFamilies) {
    if (!path.starts_with(family.prefix)) continue;
    const std::string name = path.substr(std::string(family.prefix).size());
    const auto session = server.find_session(name);
    const bool call = std::string(family.prefix) == "/call/";
    if (!session && call && server.maker().policy() != MakingPolicy::Off) {
      if (name.empty() || name.size() > server.maker().options().max_name_length ||
          name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.") != std::string::npos)
        return text_reply(404, "no call " + name + ": a room's name is 1-" + std::to_string(server.maker().options().max_name_length) +
                                   " letters, digits, - _ .");
      return http_reply(200, "text/html; charset=utf-8", room_page(server, request, name) + invite(name, request.header("host"), server.tls() != nullptr),
                        kIsolatedPage);
    }
    if (!session || !family.shows(*session)) return text_reply(404, family.missing + name);
    const std::string attributes = std::string(family.prefix) == "/turntable/" ? presenter_attribute(request.path) : "";
    const bool scene = std::string(family.prefix) == "/scene/";
    // A scene's page offers its editor (pages/scene.js) the model's replacement.
    std::string page = element_page(family.element, session->name(), request.header("host"), family.invitation, server.tls() != nullptr, attributes,
                                    scene ? "/pages/scene.js" : "");
    if (call) page += invite(session->name(), request.header("host"), server.tls() != nullptr);
    if (scene)
      page += "<form class=\"upload replace\" hidden><label class=drop>Replace the model (everyone in the scene gets the new one)"
              "<input type=file multiple></label><progress hidden max=1 value=0></progress><p class=status role=status></p></form>";
    return http_reply(200, "text/html; charset=utf-8", std::move(page), *family.headers);
  }
  return std::nullopt;
}

// The front page (SPEC N12): what the server offers, each use with a picture of it, a button
// that starts a call, a control that makes a scene of a model the visitor brings (its script is
// pages/front.js), and the operator's own sessions with their members now. Sessions people made
// themselves (rooms, uploaded scenes) are not listed: their links are their makers' to share.
std::string front_page(Server& server) {
  const SessionMaker& maker = server.maker();
  const bool making = maker.policy() != MakingPolicy::Off, token = maker.policy() == MakingPolicy::Token;
  std::string products, scenes, calls;
  for (const auto& [name, session] : server.sessions()) {
    if (session->stored().maker == MadeBy::Room || session->stored().maker == MadeBy::Upload) continue;
    const protocol::Snapshot& state = session->state();
    const std::string members = std::to_string(session->members()) + (session->members() == 1 ? " member" : " members") + " now";
    const std::string n = html_escape(name);
    if (!state.product.directions.empty()) {
      const auto listing = session->listing();
      std::string picture;
      // Its first photo, as the static files serve it.
      const auto first = std::find_if(state.assets.begin(), state.assets.end(), [](const auto& a) { return a.kind == protocol::AssetKind::Samples; });
      if (listing && first != state.assets.end())
        for (const auto& [file, f] : listing->files)
          if (!f.cell && f.hash == first->hash) picture = "<img src=\"/products/" + n + "/" + html_escape(file) + "\" alt=\"\" loading=lazy>";
      products += "<li><a href=\"/turntable/" + n + "\">" + picture + "<span>" + n + "</span></a><small>" +
                  std::to_string(state.product.directions.size()) + " photos, " + members + "</small></li>";
    } else if (session->call()) {
      calls += "<li><a href=\"/call/" + n + "\"><span>" + n + "</span></a><small>" + members + "</small></li>";
    } else {
      scenes += "<li><a href=\"/scene/" + n + "\"><span>" + n + "</span></a><small>" + html_escape(state.style.renderer) + ", " + members + "</small></li>";
    }
  }
  const auto list = [](const std::string& items, const char* none) { return items.empty() ? std::string("<p class=none>") + none + "</p>" : "<ul>" + items + "</ul>"; };
  const std::string token_field = token ? "<label class=token>Creator token <input name=token autocomplete=off></label>" : "";
  const std::string name = html_escape(server.config().name);
  std::string body =
      "<!doctype html><html lang=en><meta charset=utf-8><meta name=viewport content=\"width=device-width, initial-scale=1\">"
      "<title>" + name + "</title><link rel=stylesheet href=\"/pages/front.css\"><script type=module src=\"/pages/front.js\"></script>"
      "<header><h1>" + name + "</h1><p>Calls, products and scenes, each drawn in your browser from a few bytes: faces redrawn from "
      "expression codes, products turned between their photos, models in comic, sketch, hatching or painted styles.</p></header><main>"
      "<section class=use><img src=\"/pages/call.jpg\" alt=\"A call: every member's face redrawn from codes\"><div><h2>Calls</h2>"
      "<p>Everyone seen and heard from their own camera and microphone, at a few kilobits a second. Send the link: whoever has it joins.</p>";
  if (making) body += "<form class=start action=\"/call/\" method=get>" + token_field + "<button>Start a call</button></form>";
  else body += "<p class=none>This server opens no rooms for visitors.</p>";
  body += list(calls, "") + "</div></section>"
          "<section class=use><img src=\"/pages/product.jpg\" alt=\"A product turned between its photos\"><div><h2>Products</h2>"
          "<p>Real photos of a product, turned by the customer: every view between them drawn on the spot. A shop puts them here with one command "
          "(<code>inkwire-server add-product</code>).</p>" + list(products, "No products here yet.") + "</div></section>"
          "<section class=use><img src=\"/pages/scene.jpg\" alt=\"A model drawn in a comic style\"><div><h2>Scenes</h2>"
          "<p>One model in one style for a class or a review: everyone sees the same, and the editor's changes reach all.</p>";
  if (making)
    body += "<form class=upload>" + token_field + "<label class=drop>New scene: pick or drop a model (glTF with its files, GLB, OBJ with MTL and textures, "
            "PLY, OFF, STL, 3DS, FBX, ...)<input type=file name=model multiple></label><progress hidden max=1 value=0></progress>"
            "<p class=status role=status></p></form>";
  body += list(scenes, "") + "</div></section></main>\n";
  return http_reply(200, "text/html; charset=utf-8", body);
}

}  // namespace inkwire::server

#include "client/viewer/session_view.hpp"

#include <cstdio>

#include "client/render/styles.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

}  // namespace

void SessionView::update(const protocol::Snapshot& state, const AssetFiles& asset_files) {
  state_ = state;
  // The content the state's kind names; a session that changed kind starts its content afresh.
  const bool conference = state.kind == protocol::SessionKind::Conference, product = !state.product.directions.empty();
  if (conference && !std::holds_alternative<ConferenceContent>(content_)) content_.emplace<ConferenceContent>();
  if (!conference && product && !std::holds_alternative<ProductContent>(content_)) content_.emplace<ProductContent>();
  if (!conference && !product && !std::holds_alternative<SceneContent>(content_)) content_.emplace<SceneContent>();
  const bool new_content = std::visit(Overloaded{[](std::monostate) { return false; },
                                                 [&](auto& content) { return content.update(state, asset_files); }}, content_);
  update_style(state, new_content);
}

void SessionView::update_style(const protocol::Snapshot& state, bool new_content) {
  std::string key = state.style.renderer;
  for (const std::string& s : state.style.settings) key += " " + s;
  if (key == style_key_ && !new_content) return;
  const auto each = [&](auto&& act) { std::visit(Overloaded{[](std::monostate) {}, act}, content_); };
  try {
    style_params(state.style.renderer, state.style.settings);
    each([&](auto& content) { content.set_style(state.style); });
    std::string backdrop = default_backdrop(state.style.renderer, state.style.settings);
    each([&](auto& content) { backdrop = content.backdrop(state.style); });
    backdrop_.emplace(BackdropSpec::parse(backdrop));
    style_key_ = key;
    style_error_.clear();
  } catch (const Error& e) {
    style_error_ = "style '" + state.style.renderer + "' refused: " + e.what();
    std::fprintf(stderr, "inkwire-client: %s (keeping the previous style)\n", style_error_.c_str());
    each([&](auto& content) { content.keep_after_refusal(new_content); });
    // Nothing drawn yet: the default's backdrop, so the session still shows.
    if (!backdrop_) backdrop_.emplace(BackdropSpec::parse(default_backdrop("default")));
    style_key_ = key;
  }
}

const std::string& SessionView::content_error() const {
  static const std::string none;
  return std::visit(Overloaded{[](std::monostate) -> const std::string& { return none; },
                               [](const auto& content) -> const std::string& { return content.error(); }}, content_);
}

ConferenceContent& SessionView::conference() {
  if (!std::holds_alternative<ConferenceContent>(content_)) content_.emplace<ConferenceContent>();
  return std::get<ConferenceContent>(content_);
}

void SessionView::update_call(const protocol::Roster& roster, const std::map<uint16_t, AssetFiles>& files) { conference().update_call(roster, files); }

const CallGrid& SessionView::call() const {
  static const CallGrid none;
  const auto* c = std::get_if<ConferenceContent>(&content_);
  return c ? c->call() : none;
}

std::optional<ExpressionState> SessionView::expression() const {
  const auto* c = std::get_if<ConferenceContent>(&content_);
  return c ? c->expression() : std::nullopt;
}

int SessionView::painted_frames() const {
  const auto* c = std::get_if<ConferenceContent>(&content_);
  return c ? c->painted_frames() : 0;
}

TurntableView* SessionView::turntable() {
  auto* p = std::get_if<ProductContent>(&content_);
  return p ? p->turntable() : nullptr;
}

void SessionView::draw(glm::ivec2 viewport, double time_seconds, long frame) {
  if (!backdrop_) backdrop_.emplace(BackdropSpec::parse("paper"));
  backdrop_->draw();
  std::visit(Overloaded{[](std::monostate) {},
                        [&](ProductContent& product) { product.draw(viewport, orbit_); },
                        [&](auto& content) { content.draw(viewport, time_seconds, frame, state_, *backdrop_); }}, content_);
}

}  // namespace inkwire

// Who may change what (server/authority.hpp, SPEC W8), as a table: session kind, whether it
// names an editor token, the member's role, the change, and whether it is allowed.
#include <gtest/gtest.h>

#include "server/authority.hpp"
#include "server/session_token.hpp"

using namespace inkwire::server;
using inkwire::protocol::MessageType;
using inkwire::protocol::SessionKind;

namespace {

struct Case {
  SessionKind kind;
  bool editor_token;
  Role role;
  MessageType change;
  bool allowed;
};

const Case kCases[] = {
    // A product is read-only to visitors, with or without an editor token; its editor does all.
    {SessionKind::Turntable, true, Role::Visitor, MessageType::ObjectPose, false},
    {SessionKind::Turntable, true, Role::Visitor, MessageType::StyleChange, false},
    {SessionKind::Turntable, true, Role::Visitor, MessageType::CameraPose, false},
    {SessionKind::Turntable, false, Role::Visitor, MessageType::ObjectPose, false},
    {SessionKind::Turntable, true, Role::Editor, MessageType::ObjectPose, true},
    {SessionKind::Turntable, true, Role::Editor, MessageType::StyleChange, true},
    // A scene with an editor token follows its editors; without one everyone steers.
    {SessionKind::Scene, true, Role::Visitor, MessageType::StyleChange, false},
    {SessionKind::Scene, true, Role::Visitor, MessageType::CameraPose, false},
    {SessionKind::Scene, true, Role::Visitor, MessageType::ObjectPose, false},
    {SessionKind::Scene, true, Role::Editor, MessageType::CameraPose, true},
    {SessionKind::Scene, false, Role::Visitor, MessageType::StyleChange, true},
    {SessionKind::Scene, false, Role::Visitor, MessageType::CameraPose, true},
    // A conference's faces come from the server's analysis, never from a member's codes.
    {SessionKind::Conference, false, Role::Visitor, MessageType::ExpressionCode, false},
    {SessionKind::Conference, true, Role::Visitor, MessageType::StyleChange, false},
    {SessionKind::Conference, true, Role::Editor, MessageType::StyleChange, true},
    {SessionKind::Conference, false, Role::Visitor, MessageType::StyleChange, true},
};

}  // namespace

TEST(AuthorityTest, EachKindOfSessionAllowsWhatItsTableSays) {
  for (const Case& c : kCases) {
    const std::string reason = refusal({.kind = c.kind, .has_editor_token = c.editor_token}, c.role, c.change);
    EXPECT_EQ(reason.empty(), c.allowed) << "kind " << int(c.kind) << ", editor token " << c.editor_token << ", role " << int(c.role)
                                         << ", change " << int(c.change) << ": '" << reason << "'";
  }
}

TEST(AuthorityTest, ARefusalSaysWhoMayAndWhat) {
  EXPECT_EQ(refusal({.kind = SessionKind::Turntable, .has_editor_token = true}, Role::Visitor, MessageType::ObjectPose),
            "only the product's editor may present or turn the object here; your view is your own, and you may follow a presenter");
  EXPECT_EQ(refusal({.kind = SessionKind::Scene, .has_editor_token = true}, Role::Visitor, MessageType::StyleChange),
            "only the session's editors may change the style; you follow them");
}

TEST(AuthorityTest, TheEditorTokenMakesAnEditorAWrongOneIsNoVisitor) {
  const std::string none, session = hash_token("s3cret"), editor = hash_token("ed1tor");
  // An open session with an editor token: no token is a visitor, the editor token an editor,
  // anything else a guess at the editor token.
  EXPECT_EQ(role_of(none, editor, ""), Role::Visitor);
  EXPECT_EQ(role_of(none, editor, "ed1tor"), Role::Editor);
  EXPECT_EQ(role_of(none, editor, "ed1to"), std::nullopt);
  // A session with both: the editor token admits on its own; the session token a visitor.
  EXPECT_EQ(role_of(session, editor, "ed1tor"), Role::Editor);
  EXPECT_EQ(role_of(session, editor, "s3cret"), Role::Visitor);
  EXPECT_EQ(role_of(session, editor, ""), std::nullopt);
  // Without an editor token nobody is an editor; an open session lets any token in, as before.
  EXPECT_EQ(role_of(none, none, "anything"), Role::Visitor);
  EXPECT_EQ(role_of(session, none, "s3cret"), Role::Visitor);
  EXPECT_EQ(role_of(session, none, "ed1tor"), std::nullopt);
}

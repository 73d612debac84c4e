#pragma once
// Every message of the Inkwire wire protocol (protocol/SPEC.md), each with one serialise
// function that reads, writes and measures it. Limits are part of the protocol: a peer sending
// more is malformed and is disconnected with an Error message.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "common/face/expression.hpp"
#include "protocol/streams.hpp"

namespace inkwire::protocol {

inline constexpr uint32_t kMagic = 0x574B4E49;  // the bytes "INKW" read as a little-endian u32
inline constexpr uint16_t kVersion = 9;  // 2: snapshots describe a turntable's product; 3: calls, refused changes; 4: zoom levels; 5: permissions;
                                         // 6: face video; 7: voice route; 8: rooms opened on joining, their host;
                                         // 9: member faces in layers with their head's pose
// The oldest version a server still serves (protocol/versions.hpp says what such a peer is sent instead).
inline constexpr uint16_t kOldestVersion = 7;

inline constexpr size_t kMaxName = 64;           // session, client and server names
inline constexpr size_t kMaxToken = 128;
inline constexpr size_t kMaxReason = 512;
inline constexpr size_t kMaxRenderer = 128;      // "hatching+sketch-charcoal"
inline constexpr size_t kMaxSetting = 300;       // one KEY=VALUE
inline constexpr size_t kMaxSettings = 64;
inline constexpr size_t kMaxAssets = 1024;       // per session: a 360-photo product with mattes, plus its tween data
inline constexpr size_t kMaxProductSamples = 360; // sample photos of one product (one per degree)
inline constexpr size_t kMaxZoomLevels = 3;      // finer levels of a product's photos: 512 -> 1024 -> 2048, and one to spare
inline constexpr size_t kMaxChunk = 64 * 1024;   // asset bytes per chunk
inline constexpr size_t kMaxTween = 16 * 1024;   // one cell's tween data
inline constexpr uint64_t kMaxAssetBytes = uint64_t(1) << 30;
// Calls (SPEC F7-F13).
// What a frame may carry; the server drops what is over its own, smaller limits (server/call/)
// and counts it, so a client with a bad encoder loses a crop, not its call.
inline constexpr size_t kMaxCropBytes = 64 * 1024;    // one face crop, a JPEG of about 160 px (4-10 KB)
inline constexpr size_t kMaxVideoFrameBytes = 64 * 1024;  // one VP8 frame of the face video (a key frame of 160 px: 1-4 KB)
inline constexpr uint16_t kMaxVideoSide = 320;          // the face video's picture: 160 x 160 on the face, 320 wide while searching
inline constexpr size_t kMaxPhotoBytes = 120 * 1024;  // a member's neutral photo, JPEG
inline constexpr size_t kMaxVoiceBytes = 1275;        // one Opus packet at most (RFC 6716); 12 kbit/s x 60 ms is 90 bytes
inline constexpr size_t kMaxMembers = 64;             // members a roster lists
inline constexpr size_t kVoiceTicketChars = 32;       // a voice route's ticket: 128 random bits in hex
inline constexpr size_t kHostKeyChars = 32;           // a room's host key: 128 random bits in hex

enum class MessageType : uint16_t {
  Hello = 1, Welcome, Error, Ping, Pong, Join, Leave, Snapshot, StyleChange, CameraPose,
  ObjectPose, ExpressionCode, TweenData, AssetAnnounce, AssetRequest, AssetChunk,
  Publish, NeutralPhoto, FaceCrop, FaceRegion, VoiceFrame, MemberFace, Roster, Permissions,
  FaceVideo, KeyFrameRequest, VoiceRoute, HostKey, RoomControl, MemberLayers
};
inline constexpr uint16_t kMessageTypes = 30;

enum class SessionKind : uint8_t { Scene = 1, Turntable = 2, Conference = 3 };
// Samples: a product's sample photos in sample order; Matte: their mattes, in the same order;
// Zoom: the photos again at the product's finer levels, level after level, each in sample order.
enum class AssetKind : uint8_t { Mesh = 1, Image = 2, Samples = 3, Tween = 4, Landmarks = 5, Matte = 6, Zoom = 7 };
inline constexpr unsigned kAssetKinds = 7;
enum class ErrorCode : uint16_t {
  BadVersion = 1, Malformed = 2, NoSession = 3, BadToken = 4, NotJoined = 5, NoAsset = 6,
  TooSlow = 7, ShuttingDown = 8, Refused = 9,
  // A change this member may not make (SPEC W8): not applied, the connection stays open.
  NotAllowed = 10,
  // A room's host locked it (a join is refused: the reason names the host to ask), or removed
  // this member: clients do not join again by themselves after either.
  Locked = 11, Removed = 12
};

std::string to_string(SessionKind kind);
SessionKind session_kind_from_string(const std::string& name);  // throws Error
std::string to_string(AssetKind kind);

struct Hello {
  static constexpr MessageType type = MessageType::Hello;
  bool operator==(const Hello&) const = default;
  uint32_t magic = kMagic;
  uint16_t version = kVersion;
  std::string client_name;
};

struct Welcome {
  static constexpr MessageType type = MessageType::Welcome;
  bool operator==(const Welcome&) const = default;
  uint16_t version = kVersion;
  std::string server_name;
};

struct ErrorMessage {
  static constexpr MessageType type = MessageType::Error;
  bool operator==(const ErrorMessage&) const = default;
  ErrorCode code = ErrorCode::Refused;
  std::string reason;
};

struct Ping {
  static constexpr MessageType type = MessageType::Ping;
  bool operator==(const Ping&) const = default;
  uint64_t nonce = 0;
};

struct Pong {
  static constexpr MessageType type = MessageType::Pong;
  bool operator==(const Pong&) const = default;
  uint64_t nonce = 0;
};

// `open_room`: when no session has this name, open a call room of it (if the server lets this
// client make rooms: `token` is then its creator token); without it an unknown name is refused,
// so a typo does not make an empty room.
struct Join {
  static constexpr MessageType type = MessageType::Join;
  bool operator==(const Join&) const = default;
  std::string session, token;
  bool open_room = false;
};

struct Leave {
  static constexpr MessageType type = MessageType::Leave;
  bool operator==(const Leave&) const = default;
};

// A renderer (a registered style, or styles joined by '+') and its KEY=VALUE settings, exactly
// what `inkwire-render --style NAME --set KEY=VALUE` takes.
struct StyleChange {
  static constexpr MessageType type = MessageType::StyleChange;
  bool operator==(const StyleChange&) const = default;
  std::string renderer = "default";
  std::vector<std::string> settings;
};

struct CameraPose {
  static constexpr MessageType type = MessageType::CameraPose;
  bool operator==(const CameraPose&) const = default;
  uint32_t sequence = 0;  // per sender, increasing: receivers may drop older ones
  glm::vec3 position{0, 0, 5}, target{0}, up{0, 1, 0};
  float fov_y_degrees = 45.0f;
};

struct ObjectPose {
  static constexpr MessageType type = MessageType::ObjectPose;
  bool operator==(const ObjectPose&) const = default;
  uint32_t sequence = 0;
  glm::vec4 rotation{0, 0, 0, 1};  // unit quaternion (x, y, z, w): identity
  glm::vec3 translation{0};
  float scale = 1.0f;
};

// Eight bytes of payload (SPEC F4): what the face shows and how strongly, plus a few continuous
// parameters (e.g. mouth open, brow raise) in -127..127.
struct ExpressionCode {
  static constexpr MessageType type = MessageType::ExpressionCode;
  bool operator==(const ExpressionCode&) const = default;
  uint8_t code = 0, intensity = 0;
  uint16_t sequence = 0;
  std::array<int8_t, 4> params{};
};

// One cell of a product's tween data (control-point paths between two or three samples), in
// the cell layout of common/tween/tween_data.hpp: sent after the snapshot to members of a
// turntable session, one message per cell.
struct TweenData {
  static constexpr MessageType type = MessageType::TweenData;
  bool operator==(const TweenData&) const = default;
  uint16_t pair = 0;  // the cell's index, 0 .. Product::cells - 1
  Bytes data;
};

struct AssetAnnounce {
  static constexpr MessageType type = MessageType::AssetAnnounce;
  bool operator==(const AssetAnnounce&) const = default;
  Hash hash{};
  uint64_t size = 0;
  AssetKind kind = AssetKind::Mesh;
  std::string name;  // file name with extension, e.g. "cow.off": tells loaders the format
};

struct AssetRequest {
  static constexpr MessageType type = MessageType::AssetRequest;
  bool operator==(const AssetRequest&) const = default;
  Hash hash{};
  uint64_t offset = 0;
  uint32_t length = 0;
};

struct AssetChunk {
  static constexpr MessageType type = MessageType::AssetChunk;
  bool operator==(const AssetChunk&) const = default;
  Hash hash{};
  uint64_t offset = 0;
  Bytes data;
};

// What a turntable session shows (SPEC T11): sample photos of `width` x `height` taken from
// `directions` (unit, from the object toward the camera, azimuth about +Y from +Z), by a camera
// `distance_diagonals` bounding-box diagonals away with a `fov_y_degrees` field of view; the
// photos are the session's Samples assets in sample order (and its Matte assets, if any), and
// `cells` tween-data messages follow the snapshot. Empty (no directions) in other sessions.
// `levels` (SPEC T18): the sizes of the photos' finer levels, each larger than the one before,
// for zooming in; the session's Zoom assets hold them.
struct ImageSize {
  bool operator==(const ImageSize&) const = default;
  uint16_t width = 0, height = 0;
};
struct Product {
  bool operator==(const Product&) const = default;
  uint16_t width = 0, height = 0;
  std::vector<glm::vec3> directions;
  uint16_t cells = 0;
  float distance_diagonals = 1.4f, fov_y_degrees = 45.0f;
  std::vector<ImageSize> levels;
};

// Everything a client needs to draw a session: sent on join and whenever a client asks again.
struct Snapshot {
  static constexpr MessageType type = MessageType::Snapshot;
  bool operator==(const Snapshot&) const = default;
  std::string session;
  SessionKind kind = SessionKind::Scene;
  uint32_t revision = 0;  // counts changes since the session was created
  std::vector<AssetAnnounce> assets;
  StyleChange style;
  CameraPose camera;
  ObjectPose object;
  ExpressionCode expression;
  Product product;
};

// ---- Calls (SPEC F7-F13): every member of a conference session may publish its own face and
// voice. Times are milliseconds on the publisher's own clock (from when it started sending), one
// clock for its crops and its voice, so receivers can keep mouth and sound in step.

// What a member publishes from now on (C->S): its camera, its microphone (muted: nothing is sent).
struct Publish {
  static constexpr MessageType type = MessageType::Publish;
  bool operator==(const Publish&) const = default;
  bool camera = false, microphone = false;
};

// A member's neutral photo (C->S), taken before joining and retaken at will: the server finds
// the face and its landmarks and lists both in the roster as the member's assets.
struct NeutralPhoto {
  static constexpr MessageType type = MessageType::NeutralPhoto;
  bool operator==(const NeutralPhoto&) const = default;
  Bytes jpeg;
};

// The face region of one camera frame (C->S, at most 15 a second): the rectangle x, y, width,
// height of the frame_width x frame_height frame that the JPEG shows (scaled to about 160 px).
struct FaceCrop {
  static constexpr MessageType type = MessageType::FaceCrop;
  bool operator==(const FaceCrop&) const = default;
  uint32_t time_ms = 0;
  uint16_t frame_width = 0, frame_height = 0;
  uint16_t x = 0, y = 0, width = 0, height = 0;
  Bytes jpeg;
};

// The face region as one frame of a VP8 video (C->S, at most 15 a second; SPEC F17): a picture
// of a fixed size while it follows the face (160 x 160) showing the rectangle x, y, width, height
// of the frame_width x frame_height camera frame; the whole frame while the face is not found.
// `sequence` counts the stream's frames from its key frame on, so the server sees one missing;
// `key` is the VP8 frame's own key-frame flag (a key frame starts the stream, may change its size).
struct FaceVideo {
  static constexpr MessageType type = MessageType::FaceVideo;
  bool operator==(const FaceVideo&) const = default;
  uint32_t time_ms = 0, sequence = 0;
  uint16_t frame_width = 0, frame_height = 0;
  uint16_t x = 0, y = 0, width = 0, height = 0;
  bool key = false;
  Bytes vp8;
};

// The publisher's next face-video frame must be a key frame (S->C): the server lost its place in
// the stream (a frame refused, missing or unreadable) and decodes nothing until one comes.
struct KeyFrameRequest {
  static constexpr MessageType type = MessageType::KeyFrameRequest;
  bool operator==(const KeyFrameRequest&) const = default;
};

// A second way for this member to hear the call (S->C, to a call member on a WebSocket; SPEC
// F15): GET /voice/TICKET on the server's HTTP listener answers with the call's voice frames to
// this member, framed as on the wire, as one streamed (chunked) response. Once it is open, voice
// frames no longer come on this connection; they come back to it if the stream ends. A worker's
// fetch() is kept off the page's thread by engines that route a worker's WebSocket through it.
struct VoiceRoute {
  static constexpr MessageType type = MessageType::VoiceRoute;
  bool operator==(const VoiceRoute&) const = default;
  std::string ticket;  // kVoiceTicketChars lowercase hex digits
};

// Where the server found the publisher's face (S->C, to the publisher only): the box in frame
// pixels to crop around next, or found = false (then the next crop is the whole frame).
struct FaceRegion {
  static constexpr MessageType type = MessageType::FaceRegion;
  bool operator==(const FaceRegion&) const = default;
  bool found = false;
  uint16_t x = 0, y = 0, width = 0, height = 0;
};

// One Opus packet of a member's voice (mono, 20-60 ms). A client sends member 0; the server
// fills in the sender's member number and relays the packet as it came.
struct VoiceFrame {
  static constexpr MessageType type = MessageType::VoiceFrame;
  bool operator==(const VoiceFrame&) const = default;
  uint16_t member = 0;
  uint32_t time_ms = 0;
  Bytes opus;
};

// What a member's face shows (S->C): the expression code and intensity (of `expression`, whose
// sequence and params do not travel: 0 when read), the head's yaw, pitch and roll in degrees,
// and where it came from. 18 bytes framed.
enum class FaceSource : uint8_t { Neutral = 0, Camera = 1, Voice = 2 };
struct MemberFace {
  static constexpr MessageType type = MessageType::MemberFace;
  bool operator==(const MemberFace&) const = default;
  uint16_t member = 0;
  uint32_t time_ms = 0;  // of the crop or voice frame it was read from (the publisher's clock)
  ExpressionCode expression;
  int8_t yaw = 0, pitch = 0, roll = 0;
  FaceSource source = FaceSource::Neutral;
};

// What a member's face shows, in layers, with its head's pose (S->C, version 9; SPEC F20-F22):
// replaces member-face, which a server still sends a peer of version 7 or 8 (protocol/face_versions.hpp).
// The expression (brows, cheeks: neutral, smile, laugh, frown, surprise, sad), the mouth (0: the
// expression's own, drawn back to rest by its intensity; a viseme over it; an expression's mouth
// instead of it) and each eye's
// openness in percent of the neutral photo's (0 shut .. 200), as common/face/face_layers.hpp
// mixes them; yaw, pitch and roll in degrees, each within +-90. 22 bytes framed.
inline constexpr int kMaxPoseDegrees = 90;
struct MemberLayers {
  static constexpr MessageType type = MessageType::MemberLayers;
  bool operator==(const MemberLayers&) const = default;
  uint16_t member = 0;
  uint32_t time_ms = 0;
  int8_t yaw = 0, pitch = 0, roll = 0;
  ExpressionState expression, mouth;
  uint8_t eye_left = 100, eye_right = 100;
  FaceSource source = FaceSource::Neutral;
};

// Every member of a call (S->C, a state message: the newest replaces the last). `assets` is
// empty until the member's neutral photo is in, then the photo (kind image) and its landmarks.
struct CallMember {
  bool operator==(const CallMember&) const = default;
  uint16_t member = 0;
  std::string name;
  bool camera = false, microphone = false;
  bool speaking = false;  // among the loudest few now
  bool face_found = true; // false when the server finds no face in its camera pictures
  std::vector<AssetAnnounce> assets;
};
struct Roster {
  static constexpr MessageType type = MessageType::Roster;
  bool operator==(const Roster&) const = default;
  uint16_t you = 0;  // the receiver's own member number (0: not a member of a call)
  std::vector<CallMember> members;
  uint16_t host = 0;    // the member number of the room's host while it is in the call (0: none)
  bool locked = false;  // the host locked the room: newcomers are refused
};

// The key to a room the receiver just opened (S->C, once, after the snapshot): joining with it
// as the token makes a member the room's host again (after a reload or a dropped connection).
// Only the server's digest of it is kept.
struct HostKey {
  static constexpr MessageType type = MessageType::HostKey;
  bool operator==(const HostKey&) const = default;
  std::string key;  // kHostKeyChars lowercase hex digits
};

// What a room's host does to it (C->S): lock it to newcomers, open it again, or remove member
// `member` (its number in the roster) from the call. Refused with the reason to anyone else.
enum class RoomAction : uint8_t { Lock = 1, Unlock = 2, Remove = 3 };
struct RoomControl {
  static constexpr MessageType type = MessageType::RoomControl;
  bool operator==(const RoomControl&) const = default;
  RoomAction action = RoomAction::Lock;
  uint16_t member = 0;  // Remove only
};

// What this member may not change in its session (S->C, after the snapshot on joining; SPEC W8):
// each change the server would refuse it, with the reason it would give, so a client can turn
// those controls off beforehand instead of having its change undone. Empty: nothing is refused.
struct Permissions {
  static constexpr MessageType type = MessageType::Permissions;
  bool operator==(const Permissions&) const = default;
  struct Refused {
    bool operator==(const Refused&) const = default;
    MessageType change = MessageType::StyleChange;  // style-change, camera-pose, object-pose or expression-code
    std::string reason;
  };
  std::vector<Refused> refused;
};

// Alternatives in MessageType order: index + 1 == type code.
using Message = std::variant<Hello, Welcome, ErrorMessage, Ping, Pong, Join, Leave, Snapshot, StyleChange, CameraPose,
                             ObjectPose, ExpressionCode, TweenData, AssetAnnounce, AssetRequest, AssetChunk,
                             Publish, NeutralPhoto, FaceCrop, FaceRegion, VoiceFrame, MemberFace, Roster, Permissions,
                             FaceVideo, KeyFrameRequest, VoiceRoute, HostKey, RoomControl, MemberLayers>;

MessageType type_of(const Message& m);
const char* name_of(MessageType type);

// State messages: only the latest of each matters, so queues may replace a pending one.
bool is_state(MessageType type);
// Applies a style, camera, object or expression change to a session's snapshot and counts it
// in the revision; false (and nothing changed) for any other message. Server and clients both
// keep their copy of a session's state with it.
bool apply_state_change(Snapshot& snapshot, const Message& change);

// The expression a code from the wire shows: nothing for codes this version does not know.
std::optional<ExpressionState> expression_state(const ExpressionCode& message);

}  // namespace inkwire::protocol

#pragma once
// Which part of the camera frame a publisher's face video shows (SPEC F17). The server reports
// where it found the face after every picture, and the next picture shows that region; when the
// face moved far or the region's size changed much, the video starts again with a key frame. A
// crop held still while the face stayed inside it showed a still face the same picture over and
// over, and the landmark model reads a face a little otherwise with every few pixels its
// picture's edges move: held, one framing decided the whole expression; following the reports,
// the analyst's smoothing takes in several (held-out Yale faces through VP8: 0.731 read right
// against 0.673, medians of ten and six runs, at the same bit rate). client/web/call/camera.js
// repeats this rule; both are pinned by tests/golden/warp-vectors.json ("face_crop").
#include "protocol/messages.hpp"

namespace inkwire {

inline constexpr int kFaceVideoSide = 160;    // the face video's picture while it follows the face
inline constexpr int kFaceSearchWidth = 320;  // ... and the whole frame's, scaled, until the face is found

struct FaceCropChoice {
  protocol::FaceRegion region;  // the crop to show
  bool jumped = false;          // far from the last one: a key frame
};

// `shown`: the crop the video shows now (found = false: the whole frame); `reported`: the
// server's latest region, found, in a frame_width x frame_height frame. The crop is square (the
// video's picture is, and a face stretched one way reads as another expression): the reported
// region's longer side, moved into the frame, or the frame's shorter side when it is longer.
FaceCropChoice follow_face(const protocol::FaceRegion& shown, const protocol::FaceRegion& reported, int frame_width, int frame_height);

// The face video's picture while the face is not found: the whole frame scaled so neither side
// passes kFaceSearchWidth (a portrait camera too: the server refuses a side over 320), even
// sides (VP8 pictures are 4:2:0), at least 16.
struct PictureSize {
  int width = 0, height = 0;
};
PictureSize search_picture_size(int frame_width, int frame_height);

}  // namespace inkwire

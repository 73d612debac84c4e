#pragma once
// Which part of the camera frame a publisher's face video shows (SPEC F17). The server reports
// where it found the face after every picture; a crop that moved with every report would cost
// bits and show no more, so the crop stays while the face stays well inside it, moves when the
// face has drifted, and jumps (the video then starts again with a key frame) when the face moved
// far or the crop's size changed much. client/web/call/camera.js repeats this rule; both are
// pinned by tests/golden/warp-vectors.json ("face_crop").
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

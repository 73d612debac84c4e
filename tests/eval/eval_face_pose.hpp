#pragma once
// `inkwire-eval face-pose`: the face the others see against the face that was there (SPEC F20).
// Clips with head motion are read by the server's own reading of a member's camera
// (server/face/face_reader.hpp) into the faces a call sends, when it sends them (its streams:
// server/face/layers_stream.hpp), and drawn as the receiver's renderer draws them at each frame's
// time (client/render/face/face_reconstructor.hpp, tweened), twice: as before poses travelled
// (the one code, the head held as in the neutral photo) and with the pose and the layers; the
// server's analyser then reads each drawn face again. Figures: head pose error
// (median degrees, all frames and where the sender's head is tilted more than 8 degrees), the
// landmarks' error normalised by the distance between the outer eye corners (NME, as 300-W
// reports it; the drawn face moved and scaled onto the sender's, since a call sends no place in
// the frame, turned not at all) and the nose's place between the eyes (the simplest reading of a
// turn: its x in the face frame) correlated with the sender's.
//
// A clip is cut into tracks: frames in a row where the largest face the detector finds stays
// about where it was (a cut or a jump starts another). Each track's first face is its member's
// neutral photo, as a member joining with that frame would have it.
// Yale faces: each subject's normal photo is the neutral one, and the same photo turned in the
// picture (roll -30..30 degrees) and moved is the sender's frame.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace inkwire::eval {

struct FacePoseOptions {
  std::string clip;                 // a video (e.g. opencv-doc's Megamind.avi); empty: none
  std::filesystem::path yale;       // a folder of subjectNN_normal photos; empty: none
  std::filesystem::path images_dir; // side-by-side sheets of some frames (sender | before | now, plain, comic, painterly)
  int limit = 0;                    // frames of the clip at most (0: all)
};

nlohmann::json run_face_pose(const FacePoseOptions& options);

// The pose of the face in `picture` against `neutral` (a photo of the same face), as the call's
// analyst reads it: {"yaw", "pitch", "roll"} in degrees. Throws when either shows no face.
nlohmann::json read_head_pose(const std::filesystem::path& neutral, const std::filesystem::path& picture);

}  // namespace inkwire::eval

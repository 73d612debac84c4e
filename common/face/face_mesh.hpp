#pragma once
// The mesh a face is redrawn over (SPEC F5): its neutral photo's 68 landmarks, a fixed ring of
// anchors around the face and the image border, triangulated. The landmarks' points follow the
// received expression; the anchors and border stay, so the deformation fades out between them.
// When the photo's mouth is closed, the triangles inside the inner lips read a strip of dark
// mouth-cavity colour under the photo (the atlas) instead of stretched lips. The browser draws
// faces with this same code, compiled to WebAssembly (client/web/module/face_module.cpp), so
// the mesh exists once.
#include <vector>

#include <glm/vec4.hpp>

#include "common/face/expression_templates.hpp"
#include "common/image.hpp"
#include "common/tween/warp_mesh.hpp"

namespace inkwire {

inline constexpr int kCavityRows = 8;  // the atlas strip under the photo that cavity triangles read

struct FaceMesh {
  // Per point: {where it reads the atlas, where it is drawn (rewritten per frame where it follows
  // a landmark), unused}.
  WarpMesh mesh;
  std::vector<int> landmark_of;  // per point: the landmark it follows, or -1 where it stays
};

// The mesh of a `width` x `height` photo whose face has `landmarks` (image pixels, checked by the
// caller to lie inside the photo).
FaceMesh build_face_mesh(const FaceLandmarks& landmarks, const ExpressionTemplates& templates, int width, int height);

// The mouth cavity's colour: the photo's lip colour darkened (a closed mouth has no inside).
glm::u8vec4 cavity_colour(const Image& photo, const FaceLandmarks& landmarks);

}  // namespace inkwire

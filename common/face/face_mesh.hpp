#pragma once
// The mesh a face is redrawn over (SPEC F5, F20): its neutral photo's 68 landmarks, anchors around
// the face (forehead, the head's outline over the hair, the neck) and the image border,
// triangulated. The landmarks' points follow the received expression; every point but the border
// has a place on the head with a depth (common/face/face_depth.hpp), so the face, its hair and,
// half way, its neck turn with the head's pose while the border stays. When the photo's mouth is
// closed, the triangles inside the inner lips read a strip of dark mouth-cavity colour under the
// photo (the atlas) instead of stretched lips. The browser draws faces with this same code,
// compiled to WebAssembly (client/web/module/face_module.cpp), so the mesh exists once.
#include <vector>

#include <glm/vec3.hpp>
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
  // Per point: where it lies on the head (the neutral photo's face frame, with depth; a
  // landmark's x and y move with the expression), and how far it turns with the head: 1 the face
  // and hair, 0.5 the neck, 0 the image border.
  std::vector<glm::vec3> head_point;
  std::vector<float> follows;
};

// The mesh of a `width` x `height` photo whose face has `landmarks` (image pixels, checked by the
// caller to lie inside the photo).
FaceMesh build_face_mesh(const FaceLandmarks& landmarks, const ExpressionTemplates& templates, int width, int height);

// The mouth cavity's colour: the photo's lip colour darkened (a closed mouth has no inside).
glm::u8vec4 cavity_colour(const Image& photo, const FaceLandmarks& landmarks);

}  // namespace inkwire

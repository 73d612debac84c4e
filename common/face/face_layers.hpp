#pragma once
// What a face shows, in layers (SPEC F21-F22), as the server reads a member's camera (and voice)
// and the receiver draws it: the expression (its brows, cheeks and face), the mouth, and each
// eye's openness, each on its own, mixed. A smile while talking is the expression smile with the
// mouth's visemes over it; a blink is both eyes' openness falling to 0 and back; a wink one.
//
// The mouth layer says what the mouth does:
//   neutral      the expression's own mouth (a smile's, a surprise's open jaw), drawn back towards
//                the mouth at rest by the mouth's intensity (0: the expression's own, 255: at rest);
//   a viseme     that mouth shape at its intensity over the expression's own (a smile keeps its
//                corners while the jaw opens and closes with the syllables);
//   an expression that expression's mouth at the mouth's intensity instead of the expression's.
// Eye openness is against the neutral photo's, in percent: 0 shut, 100 as in the photo, wider
// above (at most 200). The eyes' shape in an expression (a smile's narrowing) is in it: templates
// do not move the lids.
#include <cstdint>

#include "common/face/expression.hpp"
#include "common/face/expression_templates.hpp"
#include "common/face/head_pose.hpp"

namespace inkwire {

struct FaceLayers {
  ExpressionState expression;  // the face: neutral, smile, laugh, frown, surprise or sad
  ExpressionState mouth;       // neutral (the expression's own), a viseme, or an expression's mouth
  uint8_t eye_left = kEyeOpen, eye_right = kEyeOpen;  // the eye on the image's left, and right
  bool operator==(const FaceLayers&) const = default;
};

// Everything a face shows at a moment: its layers and its head's pose.
struct FaceState {
  FaceLayers layers;
  HeadPose pose;
  bool operator==(const FaceState&) const = default;
};

// One code as layers (a client or recording of before layers, a session-wide speaker's code):
// eyes closed and winks become the eyes' openness, visemes the mouth, the rest the expression
// with the eyes as its template leaves them.
FaceLayers layers_of(ExpressionState state, const ExpressionTemplates& templates = shipped_templates());
// The one code that says most of what `layers` show, as a client before layers is sent: an open
// mouth first, then shut eyes, then the expression (as the selector's single code chose).
ExpressionState dominant_expression(const FaceLayers& layers);

// The neutral face's landmarks (image pixels) as `layers` show them.
FaceLandmarks apply_layers(const FaceLandmarks& neutral, const ExpressionTemplates& templates, const FaceLayers& layers);

// How open the eyes are in a template at full intensity, against a neutral eye of the mean
// face's lid gap (percent, as the layer counts it).
uint8_t template_eye_openness(const ExpressionTemplates& templates, Expression e, uint8_t intensity, bool left);

}  // namespace inkwire

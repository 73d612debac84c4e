#pragma once
// Angles from the matches (SPEC T19): a turntable that speeds up and slows down photographs its
// turn unevenly, and a product that assumes even steps swings and stalls as it is turned.
//
// A point of the object at (u, w) on the turntable (u across the picture at the first photo, w
// toward its camera) turned by a photo's azimuth a appears at x = x0 + X / (1 - g Z) across the
// picture, X = u cos(a) - w sin(a), Z = u sin(a) + w cos(a), whatever the camera's height (its
// right-hand direction stays level; a point's height only scales its track), g being the
// perspective (0 for a distant camera). So corners tracked through a few photos each follow a
// sinusoid, and every photo's azimuth, every row's axis column x0 and perspective g and every
// track's (u, w) are found together by least squares (Levenberg-Marquardt): the unit length of
// (cos a, sin a) fixes what ratios of neighbouring steps alone cannot, the absolute turn (those
// were tried first and drift round the ring). A photo's azimuth is fitted from every track
// through it, so one plain photo does not break the chain; where a photo has too few tracks it
// is spaced evenly between its fitted neighbours.
//
// Which way it turned: seen from the camera the turn reads the same both ways (a -> -a, w -> -w),
// except for perspective: the nearer side of the object moves more. The fit runs the turn
// forward and, with it, a focal length; a negative one means the turntable turned the other way
// (the camera's azimuth falls from photo to photo), and the steps come out negative. A lens so
// long, or an object so small, that the perspective is within three standard errors of none
// leaves the turn forward.
//
// Tracks: Shi-Tomasi corners followed photo to photo by pyramidal Lucas-Kanade, kept while
// tracking back lands within half a pixel, inside the matte and away from the outline (whose
// corners slide over the surface instead of turning with it), on the photos read again at up to
// kTurnSide pixels (a point moves a few pixels between photos 10 degrees apart: a tenth of a
// pixel matters).
#include <vector>

#include "server/products/photo_folder.hpp"

namespace inkwire {

inline constexpr int kTurnSide = 1024;
inline constexpr float kClearlyBetterFit = 0.8f;  // the uneven fit's residual against the even one's

struct TurnSteps {
  std::vector<float> degrees;  // per column, the turn from it to the next (the last closes the ring); 360 in all, or -360
  float field_of_view = 0;     // the photos' longer side over the focal length fitted (negative: the fit ran the turn backwards)
  float field_of_view_error = 0;  // its standard error
  bool direction_known = false;   // the perspective is three standard errors from none: it tells which way the turntable turned
  std::vector<int> tracked;    // per column, the tracked points through its photos (all rows)
  int fitted = 0;              // columns with enough of them to fit; the others are spaced evenly between fitted ones
  float residual = 0;          // pixels, root mean square of the tracks about their sinusoids
  float even_residual = 0;     // the same, the same observations fitted with evenly spaced azimuths
  // Whether the uneven turn explains the tracks clearly better than even steps: a turntable
  // that stepped evenly (a stepper motor, a rendered product) keeps its even steps, whatever
  // noise the fit with a free angle per photo soaks up.
  bool uneven() const { return residual < kClearlyBetterFit * even_residual; }
};

// The steps of a folder whose rows go all the way round, from its photos read again at up to
// kTurnSide pixels (from `photos.folder`; photos held in memory only are measured as they are).
TurnSteps turn_steps_from_photos(const PhotoFolder& photos);

// How far each found azimuth (degrees) is from the truth once the two are turned to line up best
// (which photo is at "0 degrees" is a convention: only the turns between photos show): for
// measuring the above on photos whose turn is known.
std::vector<double> azimuth_errors(const std::vector<float>& found, const std::vector<float>& truth);

// Every row's photos set at azimuths turning by `steps_degrees` (per column) from the first
// photo's, at the row's elevation as it was.
void set_turn_steps(PhotoFolder& photos, const std::vector<float>& steps_degrees);

// The pipeline's turn stage, the first after reading (it follows corners on the photos as shot):
// photos whose turn no step, arc or calibration gave (`even_turn_assumed`) get their steps from
// the tracks above, unless even steps fit them about as well; says what it found through
// `progress`. Does nothing to other folders.
void find_turn_from_matches(PhotoFolder& photos, const PairProgress& progress = {});

}  // namespace inkwire

// The objects' silhouettes through a lens (swell/dataset/sensor.h): the
// amodal masks and truncation shares of a sensor frame's labels, from those
// of the pinhole frame they are resampled from. Library-internal.
#pragma once

#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"

#include <cstddef>
#include <vector>

namespace swell::detail {

// Fills out.amodal with each of wide's amodal masks resampled as the
// instance image is (`from[i]`: the pinhole pixel pixel i takes its labels
// from), and each object's truncation: the share of its whole silhouette in
// the pinhole frame (wide's silhouettePixels) whose rays image `c` does not
// show (past its border, or past the lens's fold). The pinhole frame is
// centred on the optical axis, its focal length pinholeFocal_px.
void distortSilhouettes(const FrameLabels& wide, const LensDistortion& lens, const CameraCalibration& c,
                        double pinholeFocal_px, const std::vector<std::size_t>& from, FrameLabels& out);

} // namespace swell::detail

#pragma once
// Exact Euclidean distance transform of a binary image (Meijster, Roerdink & Hesselink, "A
// general algorithm for computing distance transforms in linear time", 2000), in integers.
// Its output is bit for bit that of cv::distanceTransform(DIST_L2, DIST_MASK_PRECISE, CV_32F)
// (Felzenszwalb & Huttenlocher's exact transform: the square root, as float, of the exact
// squared distance), at about half its single-thread cost and without its per-call buffers.

#include <opencv2/core/mat.hpp>

namespace roomscout::maps {

/// Distance [pixels] from every pixel of `binary` (CV_8U) to the nearest zero pixel, into
/// `dist` (CV_32F, reused when it has the right size). Zero pixels get 0. `binary` must hold
/// at least one zero pixel (a one-pixel frame of zeros does); throws InvalidArgument otherwise
/// or when it is not CV_8U.
void distanceTransformL2(const cv::Mat& binary, cv::Mat& dist);

}  // namespace roomscout::maps

// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004): how alike two pictures are in
// structure, not only in value. PSNR alone calls a picture shifted by a
// pixel as wrong as noise; SSIM sees it is the same picture. For grading.
#pragma once
#include <vector>

namespace glimmer {

// Mean SSIM of two grey images (values 0..1, row by row, width x height
// each) over square windows of `window` texels stepped by window / 2 (at
// least 1), with the paper's constants C1 = (0.01)^2, C2 = (0.03)^2. A
// picture smaller than the window is one window of its own size. 1 for
// identical pictures; NaN when the sizes differ from width x height.
double ssim(const std::vector<double>& a, const std::vector<double>& b, int width, int height, int window = 8);

}  // namespace glimmer

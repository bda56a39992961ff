#include <osgWater/PhotonSplat>
#include <cmath>

void osgWater::splatPhotons(const float* photons, std::size_t count, float weight, float* caustics, int size)
{
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = photons + 4 * i;
        // the same acceptance test as splat.vert (NaN fails every comparison)
        if (!(p[3] > 0.5f && p[2] > 0.0f && p[0] > -0.01f && p[0] < 1.01f && p[1] > -0.01f && p[1] < 1.01f))
            continue;
        const float e = p[2] * weight;
        if (!std::isfinite(e)) continue;
        // texel centres sit at integer + 0.5: the four around (x, y) start at floor(x - 0.5)
        const float x = p[0] * size - 0.5f, y = p[1] * size - 0.5f;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const float fx = x - x0, fy = y - y0;
        const float w[2][2] = { { (1 - fx) * (1 - fy), fx * (1 - fy) }, { (1 - fx) * fy, fx * fy } };
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const int tx = x0 + k, ty = y0 + j;
                if (tx < 0 || ty < 0 || tx >= size || ty >= size) continue;
                caustics[std::size_t(ty) * size + tx] += e * w[j][k];
            }
    }
}

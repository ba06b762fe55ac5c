// Times FastNoise2's whole-grid generation at one thread, in points per second, for the
// noises `marbling-noise`'s `--bench noise` times beside it: 2D Perlin, value, cellular
// (F1, Euclidean) and 5-octave fBm of Perlin on a 2048² grid, 3D Perlin, value and
// cellular on a 128³ grid. Best of 15 passes. The step between points is 0.01 (the same
// frequency in cycles per point as ours). Output: one line per noise,
// `fastnoise2 <name> <M points/s>`, after a line naming the SIMD level chosen.
#include <FastNoise/FastNoise.h>
#include <FastSIMD/Utility/FeatureEnums.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace {
constexpr int kSide2 = 2048;
constexpr int kSide3 = 128;
constexpr int kPasses = 15;
constexpr float kStep = 0.01f;

template <class F> double best_seconds(F&& pass) {
    double best = 1e30;
    for (int i = 0; i < kPasses; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        pass();
        auto t1 = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
    }
    return best;
}

void grid2(const char* name, const FastNoise::SmartNode<>& gen) {
    std::vector<float> out(static_cast<size_t>(kSide2) * kSide2);
    double s = best_seconds([&] {
        gen->GenUniformGrid2D(out.data(), 0.5f * kStep, 0.5f * kStep, kSide2, kSide2, kStep, kStep, 1337);
    });
    std::printf("fastnoise2 %-12s %8.1f M points/s\n", name, double(out.size()) / s / 1e6);
}

void grid3(const char* name, const FastNoise::SmartNode<>& gen) {
    std::vector<float> out(static_cast<size_t>(kSide3) * kSide3 * kSide3);
    double s = best_seconds([&] {
        gen->GenUniformGrid3D(out.data(), 0.5f * kStep, 0.5f * kStep, 0.5f * kStep, kSide3, kSide3, kSide3,
                              kStep, kStep, kStep, 1337);
    });
    std::printf("fastnoise2 %-12s %8.1f M points/s\n", name, double(out.size()) / s / 1e6);
}
}  // namespace

int main() {
    std::printf("fastnoise2 simd %s, 1 thread, best of %d\n",
                FastSIMD::GetFeatureSetString(FastSIMD::DetectCpuMaxFeatureSet()), kPasses);
    auto perlin = FastNoise::New<FastNoise::Perlin>();
    auto value = FastNoise::New<FastNoise::Value>();
    auto cellular = FastNoise::New<FastNoise::CellularDistance>();
    cellular->SetDistanceFunction(FastNoise::DistanceFunction::Euclidean);
    auto fbm = FastNoise::New<FastNoise::FractalFBm>();
    fbm->SetSource(perlin);
    fbm->SetOctaveCount(5);
    grid2("perlin2", perlin);
    grid2("value2", value);
    grid2("cellular2", cellular);
    grid2("fbm5-perlin2", fbm);
    grid3("perlin3", perlin);
    grid3("value3", value);
    grid3("cellular3", cellular);
    return 0;
}

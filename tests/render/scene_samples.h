#pragma once
// What the render tests sample: the shipped scenes, and lit pixels of an image.
#include "accuracy/scene_view.h"
#include "io/image.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace aurorawall::test {

// The names of config/scenes/*.toml under sourceDir, without the extension, sorted.
inline std::vector<std::string> shippedScenes(const std::string& sourceDir)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(sourceDir + "/config/scenes"))
        if (entry.path().extension() == ".toml")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A scene's name as a test's name ('-' becomes '_').
inline std::string testName(std::string scene)
{
    std::replace(scene.begin(), scene.end(), '-', '_');
    return scene;
}

// `count` pixels evenly spaced in row-major order among those of a width-wide image of radiances (row-major)
// at or above `floor` (none if none is).
inline std::vector<glm::ivec2> litPixels(const std::vector<glm::dvec3>& radiance, int width, double floor, int count)
{
    std::vector<glm::ivec2> lit, chosen;
    for (size_t i = 0; i < radiance.size(); ++i)
        if (glm::length(radiance[i]) >= floor)
            lit.emplace_back(int(i % size_t(width)), int(i / size_t(width)));
    for (int i = 0; i < count && !lit.empty(); ++i)
        chosen.push_back(lit[std::size_t(i) * lit.size() / std::size_t(count)]);
    return chosen;
}

// The `count` brightest pixels of a width-wide image of radiances (row-major), brightest first.
inline std::vector<glm::ivec2> brightestPixels(const std::vector<glm::dvec3>& radiance, int width, size_t count)
{
    std::vector<size_t> order(radiance.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return glm::length(radiance[a]) > glm::length(radiance[b]); });
    std::vector<glm::ivec2> chosen;
    for (size_t i = 0; i < std::min(count, order.size()); ++i)
        chosen.emplace_back(int(order[i] % size_t(width)), int(order[i] / size_t(width)));
    return chosen;
}

// Puts the frame's camera at positionKm, looking along the unit `forward` with the unit `up` (perpendicular).
inline void placeCamera(cluster::FrameState& f, glm::dvec3 positionKm, glm::dvec3 forward, glm::dvec3 up)
{
    f.cameraPositionKm = positionKm;
    f.cameraUp = up;
    f.cameraRight = glm::cross(forward, up);
    f.cameraBack = -forward;
}

// The CPU reference at every pixel of a width × height view, row-major.
inline std::vector<glm::dvec3> referenceImage(const render::ReferenceModel& model, const accuracy::SceneView& view,
                                              int width, int height)
{
    std::vector<glm::ivec2> all;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            all.emplace_back(x, y);
    return accuracy::referencePixels(model, view, all, 2);
}

// `count` pixels evenly spaced in row-major order among those at or above `floor` (none if none is).
inline std::vector<glm::ivec2> litPixels(const io::Image& image, double floor, int count)
{
    std::vector<glm::ivec2> lit, chosen;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (glm::length(accuracy::pixelRadiance(image, x, y)) >= floor)
                lit.emplace_back(x, y);
    for (int i = 0; i < count && !lit.empty(); ++i)
        chosen.push_back(lit[std::size_t(i) * lit.size() / std::size_t(count)]);
    return chosen;
}

// Every pixel of `image`, row-major.
inline std::vector<glm::ivec2> allPixels(const io::Image& image)
{
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            pixels.emplace_back(x, y);
    return pixels;
}

// `pixels` of `image` sorted brightest first, by the length of their radiance (std::sort: equals in no
// set order).
inline std::vector<glm::ivec2> brightestFirst(const io::Image& image, std::vector<glm::ivec2> pixels)
{
    std::sort(pixels.begin(), pixels.end(), [&](glm::ivec2 a, glm::ivec2 b) {
        return glm::length(accuracy::pixelRadiance(image, a.x, a.y)) > glm::length(accuracy::pixelRadiance(image, b.x, b.y));
    });
    return pixels;
}

} // namespace aurorawall::test

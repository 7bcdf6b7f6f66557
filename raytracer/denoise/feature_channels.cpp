// Reading NFOR's input out of a feature image's channels (feature_channels.hpp).
#include "raytracer/denoise/feature_channels.hpp"

#include <cmath>
#include <cstring>

#include "raytracer/input_error.hpp"

namespace sweeptrace::denoise {
namespace {

Planes gather(const ExrChannels& image, const std::string& file, const std::vector<std::string>& names, const std::string& prefix,
              bool variance) {
    Planes planes(image.width, image.height, int(names.size()));
    for (std::size_t c = 0; c < names.size(); ++c) {
        const std::string name = variance ? variance_channel_name(names[c]) : prefix + names[c];
        const std::vector<float>* values = image.find(name);
        if (!values)
            throw InputError("'" + file + "' has no channel '" + name +
                             "': denoise needs colour, features (Albedo, Ns, P.Z), their variances and Even./Odd. halves, as render --aovs writes them");
        for (std::size_t i = 0; i < values->size(); ++i) {
            const float v = (*values)[i];
            if (!std::isfinite(v) || (variance && v < 0.0f))
                throw InputError("'" + file + "': channel '" + name + "' is " + (std::isnan(v) ? "NaN" : std::isfinite(v) ? "negative" : "infinite") +
                                 " at pixel (" + std::to_string(i % std::size_t(image.width)) + ", " +
                                 std::to_string(i / std::size_t(image.width)) + ")");
        }
        std::memcpy(planes.channel(int(c)), values->data(), values->size() * sizeof(float));
    }
    return planes;
}

Buffers buffers(const ExrChannels& image, const std::string& file, const std::vector<std::string>& names) {
    return {gather(image, file, names, "", false), gather(image, file, names, "Even.", false), gather(image, file, names, "Odd.", false),
            gather(image, file, names, "", true)};
}

}  // namespace

std::string variance_channel_name(const std::string& channel) {
    const std::size_t dot = channel.find('.');
    if (dot == std::string::npos) return "Variance." + channel;
    return channel.substr(0, dot) + "Variance" + channel.substr(dot);
}

const std::vector<std::string>& color_channel_names() {
    static const std::vector<std::string> names{"R", "G", "B"};
    return names;
}

const std::vector<std::string>& feature_channel_names() {
    static const std::vector<std::string> names{"Albedo.R", "Albedo.G", "Albedo.B", "Ns.X", "Ns.Y", "Ns.Z", "P.Z"};
    return names;
}

std::vector<std::string> required_channel_names() {
    std::vector<std::string> all;
    for (const auto* names : {&color_channel_names(), &feature_channel_names()})
        for (const std::string& n : *names) {
            all.push_back(n);
            all.push_back("Even." + n);
            all.push_back("Odd." + n);
            all.push_back(variance_channel_name(n));
        }
    return all;
}

NforInput nfor_input(const ExrChannels& image, const std::string& file) {
    return {buffers(image, file, color_channel_names()), buffers(image, file, feature_channel_names())};
}

}  // namespace sweeptrace::denoise

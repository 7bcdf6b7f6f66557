#include "raytracer/scene/load_motion.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace sweeptrace {

using scene_json::Node;

void read_shutter(const Node& shutter, Camera& camera) {
    if (!shutter.value().is_array() || shutter.array_size() != 2)
        shutter.fail("must be [open, close], two numbers, got " + shutter.shown());
    const float open = shutter.element(0).number();
    const float close = shutter.element(1).number();
    if (open > close)
        shutter.fail("open (" + scene_json::format_number(open) + ") is after close (" + scene_json::format_number(close) +
                     "): give [open, close] with open <= close");
    camera.shutter = true;
    camera.shutter_open = open;
    camera.shutter_close = close;
}

void read_motion(const Node& motion, const Node& object_node, Object& object, Transform (*read_transform)(const Node&)) {
    motion.require_object({"close", "keyframes"});
    const bool close = motion.has("close"), keyframes = motion.has("keyframes");
    if (close == keyframes) motion.fail("takes exactly one of \"close\" (the pose at shutter close) and \"keyframes\"");
    std::vector<Transform> keys;
    if (close) {
        keys = {object.transform, read_transform(motion.at("close"))};
    } else {
        if (object_node.has("transform"))
            object_node.at("transform").fail("not allowed with motion.keyframes: keyframes[0] is the pose at shutter open");
        const Node list = motion.at("keyframes");
        const std::size_t n = list.array_size();
        if (n < 2 || n > static_cast<std::size_t>(kMaxMotionKeys))
            list.fail("needs 2 to " + std::to_string(kMaxMotionKeys) + " keyframes (the first at shutter open, the last at close), got " +
                      std::to_string(n));
        for (std::size_t i = 0; i < n; ++i) keys.push_back(read_transform(list.element(i)));
        object.transform = keys[0];
    }
    // Every pose the same: the object is still, and is left so (it then renders, and costs, as
    // one without the motion block).
    if (keys_equal(keys)) return;
    try {
        object.motion = make_motion(std::move(keys));
    } catch (const std::invalid_argument& e) {
        motion.fail(e.what());
    }
}

void check_motion(const Scene& scene, const Node& root, std::size_t json_objects) {
    const Node objects = root.at("objects");
    for (std::size_t i = 0; i < json_objects && !scene.camera.shutter; ++i)
        if (objects.element(i).has("motion"))  // also a motion block whose poses are all equal
            objects.element(i).at("motion").fail(
                "the object moves but the camera has no shutter, so nothing would: add \"shutter\": [0, 1] to camera, or "
                "remove the motion");
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        if (!object.motion.moving()) continue;
        // Parts split off an OBJ's mesh by material come after the listed objects; their object is
        // the listed one whose name theirs extends.
        std::size_t listed = i;
        for (std::size_t j = 0; listed >= json_objects && j < json_objects; ++j)
            if (object.name.rfind(scene.objects[j].name + " [", 0) == 0) listed = j;
        const Node at = listed < json_objects ? objects.element(listed).at("motion") : objects;
        const Material& m = scene.materials[object.material];
        if (m.emission != glm::vec3(0.0f))
            at.fail("material \"" + m.name + "\" emits: moving lights are not supported (light sampling sees objects at shutter open)");
        if (reads_texture(m))
            at.fail("material \"" + m.name + "\" reads a texture: textured moving objects are not supported (uv lookups see "
                    "objects at shutter open)");
    }
}

}  // namespace sweeptrace

#include "raytracer/scene/pbrt/pbrt_parser.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include <glm/matrix.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/pbrt/pbrt_media.hpp"
#include "raytracer/scene/pbrt/pbrt_tokenizer.hpp"
#include "raytracer/scene/pbrt/pbrt_transform.hpp"
#include "raytracer/scene/scene_transform.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace::pbrt {

namespace {

struct GraphicsState {
    glm::dmat4 ctm{1.0};
    bool reverse_orientation = false;
    std::string material;  // key of PbrtScene::materials; empty: pbrt's default diffuse 0.5
    std::shared_ptr<const AreaLight> area_light;  // shared by the levels and shapes below it (pbrt_scene.hpp)
    std::string medium_inside, medium_outside;    // MediumInterface; "" vacuum
};

constexpr std::size_t kMaxNesting = 4096;  // AttributeBegin and TransformBegin levels

constexpr const char* kDefaultMaterial = "pbrt default (diffuse 0.5)";

class Parser {
public:
    Parser(const std::filesystem::path& main_file, MaterialTranslator& materials, const FileNames& files, Diagnostics& diag)
        : materials_(materials), files_(files), diag_(diag) {
        scene_.main_file = main_file;
    }

    PbrtScene run() {
        parse_file(scene_.main_file, 0, Where{});
        if (!attributes_.empty() || !transforms_.empty())
            diag_.warn(last_, "unclosed AttributeBegin", "AttributeBegin without AttributeEnd at the end of the scene (closed there)");
        if (in_object_) diag_.fail(last_, "ObjectBegin \"" + excerpt(object_name_) + "\" is never closed: add ObjectEnd");
        resolve_media();
        return std::move(scene_);
    }

private:
    // ---- files and tokens ----
    void parse_file(const std::filesystem::path& file, int depth, const Where& from) {
        if (depth > kMaxIncludeDepth)
            diag_.fail(from, "Include nested deeper than " + std::to_string(kMaxIncludeDepth) + " files (an Include cycle?)");
        if (++files_read_ > kMaxFiles) diag_.fail(from, "more than " + std::to_string(kMaxFiles) + " files included");
        FileBytes read;
        try {
            read = read_maybe_gzipped(file, "pbrt scene", kMaxSceneFileBytes);
        } catch (const InputError& e) {
            if (depth == 0) throw;
            diag_.fail(from, std::string("Include: ") + e.what());
        }
        const std::string& text = read.bytes;
        total_bytes_ += text.size();
        if (total_bytes_ > kMaxTotalBytes)
            diag_.fail(from, "the scene and its Includes hold more than " + std::to_string(kMaxTotalBytes >> 20) + " MiB of text");
        Where here{std::make_shared<const std::string>(file.string()), 0};
        const std::vector<Token> tokens = tokenize(text, here, diag_);
        std::size_t pos = 0;
        while (pos < tokens.size()) statement(tokens, pos, here, depth);
    }

    Where at(const Where& file, const Token& t) {
        Where w = file;
        w.line = t.line;
        last_ = w;
        return w;
    }

    std::string string_arg(const std::vector<Token>& tokens, std::size_t& pos, const Where& where, const std::string& directive) {
        if (pos >= tokens.size() || tokens[pos].kind != Token::Kind::String)
            diag_.fail(where, directive + " needs a quoted name, e.g. " + directive + " \"name\"");
        return tokens[pos++].text;
    }

    double number_arg(const std::vector<Token>& tokens, std::size_t& pos, const Where& where, const std::string& directive, int count) {
        double x = 0.0;
        if (pos < tokens.size() && tokens[pos].kind == Token::Kind::Word) {
            const std::string& s = tokens[pos].text;
            const char* b = s.data() + (s.size() > 0 && s[0] == '+' ? 1 : 0);
            const auto r = std::from_chars(b, s.data() + s.size(), x);
            if (r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(x)) {
                ++pos;
                return x;
            }
        }
        diag_.fail(where, directive + " takes " + std::to_string(count) + " numbers" +
                              (pos < tokens.size() ? ", got \"" + excerpt(tokens[pos].text) + "\"" : ", the file ended"));
    }

    void numbers(const std::vector<Token>& tokens, std::size_t& pos, const Where& where, const std::string& directive, int N,
                 double* out) {
        const bool bracket = pos < tokens.size() && tokens[pos].kind == Token::Kind::Open;
        if (bracket) ++pos;
        for (int i = 0; i < N; ++i) out[i] = number_arg(tokens, pos, where, directive, N);
        if (bracket) {
            if (pos >= tokens.size() || tokens[pos].kind != Token::Kind::Close)
                diag_.fail(where, directive + " takes exactly " + std::to_string(N) + " numbers in [ ]");
            ++pos;
        }
    }

    Statement typed_statement(const std::vector<Token>& tokens, std::size_t& pos, const Where& where, const std::string& directive) {
        Statement s;
        s.where = where;
        s.type = string_arg(tokens, pos, where, directive);
        s.params = parse_params(tokens, pos, where, diag_);
        return s;
    }

    // ---- the CTM ----
    void apply(const glm::dmat4& m) {
        if (end_time_only_) return;  // motion blur's end transform: not modelled (warned at ActiveTransform)
        state_.ctm = state_.ctm * m;
    }

    void require_world(const Where& w, const std::string& directive, bool world) {
        if (world && !in_world_) diag_.fail(w, directive + " must come after WorldBegin");
        if (!world && in_world_) diag_.fail(w, directive + " must come before WorldBegin");
    }

    void statement(const std::vector<Token>& tokens, std::size_t& pos, const Where& file, int depth) {
        const Token& t = tokens[pos++];
        const Where w = at(file, t);
        if (t.kind != Token::Kind::Word)
            diag_.fail(w, "expected a directive (Shape, LookAt, ...), got " +
                              (t.kind == Token::Kind::String ? "\"" + excerpt(t.text) + "\"" : t.text) +
                              " (parameters must follow a directive)");
        const std::string& d = t.text;
        double v[16];
        if (d == "Translate") {
            numbers(tokens, pos, w, d, 3, v);
            apply(translation_matrix({v[0], v[1], v[2]}));
        } else if (d == "Scale") {
            numbers(tokens, pos, w, d, 3, v);
            glm::dmat4 s(1.0);
            s[0][0] = v[0];
            s[1][1] = v[1];
            s[2][2] = v[2];
            apply(s);
        } else if (d == "Rotate") {
            numbers(tokens, pos, w, d, 4, v);
            if (v[1] == 0.0 && v[2] == 0.0 && v[3] == 0.0) diag_.fail(w, "Rotate: the axis must not be 0 0 0");
            apply(rotation_matrix({v[1], v[2], v[3]}, v[0]));
        } else if (d == "LookAt") {
            numbers(tokens, pos, w, d, 9, v);
            const auto m = look_at({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]});
            if (!m) diag_.fail(w, "LookAt: the eye and the point looked at must differ, and up must not be parallel to the view direction");
            apply(*m);
        } else if (d == "Transform" || d == "ConcatTransform") {
            numbers(tokens, pos, w, d, 16, v);
            const glm::dmat4 m = matrix_from_pbrt(v);
            if (d == "Transform") {
                if (!end_time_only_) state_.ctm = m;
            } else {
                apply(m);
            }
        } else if (d == "Identity") {
            if (!end_time_only_) state_.ctm = glm::dmat4(1.0);
        } else if (d == "CoordinateSystem") {
            named_frames_[string_arg(tokens, pos, w, d)] = state_.ctm;
        } else if (d == "CoordSysTransform") {
            const std::string name = string_arg(tokens, pos, w, d);
            const auto it = named_frames_.find(name);
            if (it == named_frames_.end())
                diag_.warn(w, "unknown coordinate system", "CoordSysTransform \"" + excerpt(name) + "\": no such coordinate system (ignored)");
            else if (!end_time_only_)
                state_.ctm = it->second;
        } else if (d == "ReverseOrientation") {
            state_.reverse_orientation = !state_.reverse_orientation;
        } else if (d == "AttributeBegin" || d == "TransformBegin") {
            // The same limit for both stacks: a million TransformBegins took 229 MB.
            if ((d == "AttributeBegin" ? attributes_.size() : transforms_.size()) >= kMaxNesting)
                diag_.fail(w, d + " nested more than " + std::to_string(kMaxNesting) + " deep");
            if (d == "AttributeBegin") attributes_.push_back(state_);
            else transforms_.push_back(state_.ctm);
        } else if (d == "AttributeEnd" || d == "TransformEnd") {
            if (d == "AttributeEnd") {
                if (attributes_.empty()) diag_.fail(w, "AttributeEnd without a matching AttributeBegin");
                state_ = attributes_.back();
                attributes_.pop_back();
            } else {
                if (transforms_.empty()) diag_.fail(w, "TransformEnd without a matching TransformBegin");
                state_.ctm = transforms_.back();
                transforms_.pop_back();
            }
        } else if (d == "ActiveTransform") {
            if (pos >= tokens.size() || tokens[pos].kind != Token::Kind::Word)
                diag_.fail(w, "ActiveTransform takes StartTime, EndTime or All");
            const std::string which = tokens[pos++].text;
            if (which != "StartTime" && which != "EndTime" && which != "All")
                diag_.fail(w, "ActiveTransform takes StartTime, EndTime or All, got " + excerpt(which));
            if (which != "All") diag_.warn(w, "motion blur", "ActiveTransform: motion blur is not supported (the start transform is used)");
            end_time_only_ = which == "EndTime";
        } else if (d == "TransformTimes") {
            numbers(tokens, pos, w, d, 2, v);
            diag_.warn(w, "motion blur", "TransformTimes: motion blur is not supported (ignored)");
        } else if (d == "Camera") {
            require_world(w, d, false);
            scene_.camera = typed_statement(tokens, pos, w, d);
            scene_.camera_from_world = state_.ctm;
            scene_.camera_medium = state_.medium_outside;
            camera_where_ = w;
            named_frames_["camera"] = glm::inverse(state_.ctm);
            camera_seen_ = true;
        } else if (d == "Film" || d == "Sampler" || d == "PixelFilter" || d == "Integrator") {
            require_world(w, d, false);
            Statement s = typed_statement(tokens, pos, w, d);
            (d == "Film" ? scene_.film : d == "Sampler" ? scene_.sampler : d == "PixelFilter" ? scene_.filter : scene_.integrator) = std::move(s);
        } else if (d == "Accelerator") {
            require_world(w, d, false);
            typed_statement(tokens, pos, w, d);  // our own acceleration structures: nothing to translate
        } else if (d == "ColorSpace") {
            const std::string name = string_arg(tokens, pos, w, d);
            if (name != "srgb") diag_.warn(w, "colour space", "ColorSpace \"" + excerpt(name) + "\" is not supported (sRGB primaries used)");
        } else if (d == "Option") {
            const ParamList p = parse_params(tokens, pos, w, diag_);
            for (const Param& q : p.params) diag_.warn(q.where, "option " + q.name, "Option \"" + q.name + "\" is not supported (ignored)");
        } else if (d == "WorldBegin") {
            require_world(w, d, false);
            in_world_ = true;
            if (!camera_seen_) scene_.camera_from_world = state_.ctm;
            named_frames_["world"] = glm::dmat4(1.0);
            state_.ctm = glm::dmat4(1.0);
        } else if (d == "WorldEnd") {
            // pbrt-v3's end of the world block; nothing follows it in such files
        } else if (d == "Include" || d == "Import") {
            const std::string name = string_arg(tokens, pos, w, d);
            parse_file(files_.resolve(name), depth + 1, w);
        } else if (d == "MakeNamedMaterial") {
            require_world(w, d, true);
            const std::string name = string_arg(tokens, pos, w, d);
            Statement s;
            s.where = w;
            s.params = parse_params(tokens, pos, w, diag_);
            s.type = s.params.get_string("type", "", diag_);
            if (s.type.empty()) diag_.fail(w, "MakeNamedMaterial \"" + excerpt(name) + "\" needs \"string type\", e.g. \"string type\" \"diffuse\"");
            define_material(name, s);
        } else if (d == "Material") {
            require_world(w, d, true);
            const Statement s = typed_statement(tokens, pos, w, d);
            const std::string key = s.type + " (" + w.short_text() + ")";
            define_material(key, s);
            state_.material = key;
        } else if (d == "NamedMaterial") {
            require_world(w, d, true);
            const std::string name = string_arg(tokens, pos, w, d);
            state_.material = name;  // pbrt-v4 resolves the name once the scene is read: it may come later
        } else if (d == "Texture") {
            require_world(w, d, true);
            const std::string name = string_arg(tokens, pos, w, d);
            const std::string kind = string_arg(tokens, pos, w, d);
            const Statement s = typed_statement(tokens, pos, w, d);
            materials_.define_texture(name, kind, s);
        } else if (d == "AreaLightSource") {
            require_world(w, d, true);
            state_.area_light = std::make_shared<const AreaLight>(AreaLight{typed_statement(tokens, pos, w, d)});
        } else if (d == "LightSource") {
            require_world(w, d, true);
            scene_.lights.push_back({typed_statement(tokens, pos, w, d), state_.ctm});
        } else if (d == "Shape") {
            require_world(w, d, true);
            ShapeRecord r{typed_statement(tokens, pos, w, d), state_.ctm, state_.reverse_orientation, current_material(),
                          state_.area_light, state_.medium_inside, state_.medium_outside};
            add_shape(std::move(r), w);
        } else if (d == "ObjectBegin") {
            require_world(w, d, true);
            if (in_object_) diag_.fail(w, "ObjectBegin inside ObjectBegin \"" + excerpt(object_name_) + "\": close it with ObjectEnd first");
            object_name_ = string_arg(tokens, pos, w, d);
            in_object_ = true;
            attributes_.push_back(state_);
            objects_[object_name_].clear();
        } else if (d == "ObjectEnd") {
            if (!in_object_) diag_.fail(w, "ObjectEnd without ObjectBegin");
            in_object_ = false;
            if (!attributes_.empty()) {
                state_ = attributes_.back();
                attributes_.pop_back();
            }
        } else if (d == "ObjectInstance") {
            require_world(w, d, true);
            const std::string name = string_arg(tokens, pos, w, d);
            if (in_object_) diag_.fail(w, "ObjectInstance inside ObjectBegin: instances do not nest in pbrt-v4");
            const auto it = objects_.find(name);
            if (it == objects_.end()) diag_.fail(w, "ObjectInstance \"" + excerpt(name) + "\": no object of that name (define it with ObjectBegin first)");
            for (const ShapeRecord& shape : it->second) {
                charge_load_memory(shape.statement.params.bytes(), w.text(), "ObjectInstance \"" + excerpt(name) + "\"'s copy of a shape");
                ShapeRecord placed = shape;
                placed.ctm = state_.ctm * shape.ctm;
                add_shape(std::move(placed), w);
            }
        } else if (d == "MakeNamedMedium") {
            const std::string name = string_arg(tokens, pos, w, d);
            Statement s;
            s.where = w;
            s.params = parse_params(tokens, pos, w, diag_);
            if (name.empty()) diag_.fail(w, "MakeNamedMedium needs a name (\"\" is vacuum)");
            if (std::optional<nlohmann::json> m = translate_medium(s, name, state_.ctm, materials_, files_, diag_)) {
                scene_.media[name] = std::move(*m);
                scene_.medium_where[name] = s.where;
                unsupported_media_.erase(name);
            } else {
                scene_.media.erase(name);
                scene_.medium_where.erase(name);
                unsupported_media_.insert(name);
            }
        } else if (d == "MediumInterface") {
            // pbrt-v4: "inside" "outside", or one name for both sides.
            state_.medium_inside = string_arg(tokens, pos, w, d);
            state_.medium_outside = state_.medium_inside;
            if (pos < tokens.size() && tokens[pos].kind == Token::Kind::String) state_.medium_outside = tokens[pos++].text;
        } else if (d == "Attribute") {
            const std::string target = string_arg(tokens, pos, w, d);
            parse_params(tokens, pos, w, diag_);
            diag_.warn(w, "Attribute", "Attribute \"" + excerpt(target) + "\": default parameter values are not supported (ignored)");
        } else {
            diag_.fail(w, "unknown directive \"" + excerpt(d) + "\" (pbrt-v4 directives: Shape, Material, LightSource, LookAt, ...)");
        }
    }

    // Once the whole file is read (a medium may be defined after it is named, as in pbrt-v4,
    // which resolves names when it builds the scene): every shape's and the camera's medium
    // names made those of supported media, "" for unsupported ones (warned where defined); a
    // name nothing defines is an error at the statement that used it.
    void resolve_media() {
        auto resolve = [&](std::string& name, const Where& where, const char* user) {
            if (name.empty() || scene_.media.count(name)) return;
            if (unsupported_media_.count(name)) {
                name.clear();
                return;
            }
            diag_.fail(where, std::string(user) + ": its MediumInterface names medium \"" + excerpt(name) +
                                  "\", which no MakeNamedMedium defines");
        };
        for (ShapeRecord& r : scene_.shapes) {
            resolve(r.inside, r.statement.where, "Shape");
            resolve(r.outside, r.statement.where, "Shape");
        }
        resolve(scene_.camera_medium, camera_where_, "Camera");
    }

    void define_material(const std::string& name, const Statement& s) {
        MaterialResult r = materials_.translate(s, named_);
        scene_.materials[name] = r.json;
        scene_.material_where[name] = s.where;
        scene_.invisible[name] = r.invisible;
        named_[name] = std::move(r);
    }

    std::string current_material() {
        if (!state_.material.empty()) return state_.material;
        if (!scene_.materials.count(kDefaultMaterial)) {
            scene_.materials[kDefaultMaterial] = {{"type", "diffuse"}, {"albedo", {0.5, 0.5, 0.5}}};
            scene_.invisible[kDefaultMaterial] = false;
        }
        return kDefaultMaterial;
    }

    void add_shape(ShapeRecord r, const Where& w) {
        if (++shape_count_ > kMaxShapes)
            diag_.fail(w, "more than " + std::to_string(kMaxShapes) + " shapes (after instancing): too large to convert");
        if (in_object_) objects_[object_name_].push_back(std::move(r));
        else scene_.shapes.push_back(std::move(r));
    }

    MaterialTranslator& materials_;
    const FileNames& files_;
    Diagnostics& diag_;
    PbrtScene scene_;
    GraphicsState state_;
    std::vector<GraphicsState> attributes_;
    std::vector<glm::dmat4> transforms_;
    std::map<std::string, glm::dmat4> named_frames_;
    std::map<std::string, MaterialResult> named_;
    std::map<std::string, std::vector<ShapeRecord>> objects_;
    std::string object_name_;
    bool in_object_ = false, in_world_ = false, camera_seen_ = false, end_time_only_ = false;
    std::size_t files_read_ = 0, total_bytes_ = 0, shape_count_ = 0;
    Where last_;
    Where camera_where_;
    std::set<std::string> unsupported_media_;  // MakeNamedMedium of a type we do not render (warned)
};

}  // namespace

PbrtScene parse_pbrt(const std::filesystem::path& main_file, MaterialTranslator& materials, const FileNames& files,
                     Diagnostics& diag) {
    return Parser(main_file, materials, files, diag).run();
}

}  // namespace sweeptrace::pbrt

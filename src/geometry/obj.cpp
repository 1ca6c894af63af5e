#include <array>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include "geometry/mesh.h"
#include "util/read_file.h"

namespace glimmer {

namespace {

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

}  // namespace

std::uint64_t meshBytes(const Mesh& m) {
    return 2 * (std::uint64_t(m.vertices.size()) * sizeof(MeshVertex) + std::uint64_t(m.indices.size()) * 4);
}

ObjCounts countObj(const std::string& text) {
    ObjCounts c;
    std::uint64_t corners = 0;
    int lineNo = 0;
    size_t at = 0;
    while (at < text.size()) {
        ++lineNo;
        size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        size_t p = at;
        while (p < end && (text[p] == ' ' || text[p] == '\t')) ++p;
        auto word = [&](const char* w, size_t n) {
            return end - p > n && text.compare(p, n, w) == 0 && (text[p + n] == ' ' || text[p + n] == '\t');
        };
        if (word("v", 1)) ++c.positions;
        else if (word("vt", 2)) ++c.texcoords;
        else if (word("vn", 2)) ++c.normals;
        else if (word("f", 1)) {
            std::uint64_t n = 0;
            for (size_t q = p + 1; q < end;) {
                while (q < end && (text[q] == ' ' || text[q] == '\t' || text[q] == '\r')) ++q;
                if (q >= end) break;
                ++n;
                while (q < end && text[q] != ' ' && text[q] != '\t' && text[q] != '\r') ++q;
            }
            corners += n;
            if (n >= 3) c.triangles += n - 2;
            if (n >= 5) c.cuttingWork += n * n;
            if (n > c.mostCorners) c.mostCorners = n, c.mostCornersLine = lineNo;
        }
        at = end + 1;
    }
    // tinyobjloader: 3 floats a v (and as many weights), 2 a vt, 3 a vn, an
    // index triple (12 bytes) a corner before and after cutting; the Mesh: a
    // vertex, an index and a map node for every corner of every triangle,
    // then its copy on the GPU.
    c.bytes = c.positions * 24 + c.texcoords * 8 + c.normals * 12 + corners * 12 +
              c.triangles * 3 * (12 + 2 * (sizeof(MeshVertex) + 4) + 64);
    return c;
}

bool loadObj(const std::string& path, Mesh& out, std::string& error) {
    // Read here, not by tinyobjloader: only a regular file of bounded size,
    // and no .mtl file it names (materials are not used, and a model must
    // not open files the script could not name itself).
    std::string text, why;
    if (!readRegularFile(path, kMaxInputFileBytes, text, why)) {
        error = "cannot load OBJ '" + path + "': it " + why;
        return false;
    }
    return loadObjText(text, countObj(text), path, out, error);
}

bool loadObjText(const std::string& text, const ObjCounts& counts, const std::string& path, Mesh& out,
                 std::string& error) {
    if (counts.mostCorners > kMaxObjFaceCorners) {
        error = fmt::format("cannot load OBJ '{}': the face on its line {} has {} corners; Glimmer cuts faces of at "
                            "most {} corners into triangles", path, counts.mostCornersLine, counts.mostCorners,
                            kMaxObjFaceCorners);
        return false;
    }
    if (counts.cuttingWork > kMaxObjCuttingWork) {
        error = fmt::format("cannot load OBJ '{}': its faces of five corners or more are too many to cut into "
                            "triangles (corners squared add up to {}, at most {}); split them in the modeller",
                            path, counts.cuttingWork, kMaxObjCuttingWork);
        return false;
    }
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, std::string(), config)) {
        std::string reason = trimmed(reader.Error());
        if (reason.empty()) reason = "unknown error";
        error = "cannot load OBJ '" + path + "': " + reason;
        return false;
    }

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    auto vec3At = [](const std::vector<tinyobj::real_t>& a, int i) {
        const auto k = static_cast<size_t>(i) * 3;
        return glm::vec3(float(a[k]), float(a[k + 1]), float(a[k + 2]));
    };
    auto valid = [](int i, size_t count, size_t width) {
        return i >= 0 && static_cast<size_t>(i) * width + width <= count;
    };

    Mesh mesh;
    // Corners that carry their own vn are shared by (v, vt, vn); corners that
    // need the face normal cannot be shared across faces.
    std::map<std::array<int, 3>, std::uint32_t> shared;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& ids = shape.mesh.indices;
        size_t offset = 0;
        for (unsigned char fv : shape.mesh.num_face_vertices) {
            if (fv != 3 || offset + 3 > ids.size()) {  // triangulate leaves only triangles
                offset += fv;
                continue;
            }
            glm::vec3 p[3];
            bool ok = true;
            for (int k = 0; k < 3; ++k) {
                const int vi = ids[offset + k].vertex_index;
                if (!valid(vi, attrib.vertices.size(), 3)) {
                    ok = false;
                    break;
                }
                p[k] = vec3At(attrib.vertices, vi);
            }
            if (!ok) {
                error = "cannot load OBJ '" + path + "': face refers to a missing vertex";
                return false;
            }
            glm::vec3 faceNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
            const float len = glm::length(faceNormal);
            faceNormal = len > 0.f ? faceNormal / len : glm::vec3(0.f, 0.f, 1.f);

            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& id = ids[offset + k];
                const bool hasVt = valid(id.texcoord_index, attrib.texcoords.size(), 2);
                glm::vec3 n{0.f};
                if (valid(id.normal_index, attrib.normals.size(), 3))
                    n = vec3At(attrib.normals, id.normal_index);
                const float nlen = glm::length(n);
                const bool hasVn = nlen > 0.f;

                const std::array<int, 3> key{id.vertex_index, hasVt ? id.texcoord_index : -1,
                                             id.normal_index};
                if (hasVn) {
                    if (auto it = shared.find(key); it != shared.end()) {
                        mesh.indices.push_back(it->second);
                        continue;
                    }
                }
                MeshVertex v;
                v.position = p[k];
                v.normal = hasVn ? n / nlen : faceNormal;
                if (hasVt) {
                    const auto t = static_cast<size_t>(id.texcoord_index) * 2;
                    v.st = {float(attrib.texcoords[t]), float(attrib.texcoords[t + 1])};
                }
                const auto index = static_cast<std::uint32_t>(mesh.vertices.size());
                mesh.vertices.push_back(v);
                mesh.indices.push_back(index);
                if (hasVn) shared.emplace(key, index);
            }
            offset += 3;
        }
    }
    if (mesh.indices.empty()) {
        error = "cannot load OBJ '" + path + "': no faces";
        return false;
    }
    out = std::move(mesh);
    return true;
}

}  // namespace glimmer

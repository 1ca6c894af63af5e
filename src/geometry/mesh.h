// Shapes as plain vertex arrays, built on the CPU. The renderer uploads them;
// nothing here calls OpenGL.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace glimmer {

struct MeshVertex {
    glm::vec3 position{0.f};
    glm::vec3 normal{0.f, 0.f, 1.f};
    glm::vec2 st{0.f};               // texture coordinates, 0..1
    glm::vec3 tangent{0.f, 1.f, 0.f}; // glman's `Tangent` attribute (spheres: towards the north pole)
};

struct Mesh {
    enum class Primitive { Triangles, Lines, Points };
    Primitive primitive = Primitive::Triangles;
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;  // into vertices; drawn as `primitive`
    bool hasTangents = false;
    // True when no triangle can hide another (a flat quad): a target that only
    // receives one such mesh needs no depth buffer.
    bool flat = false;
};

// glman's shapes. Every triangle is counter-clockwise seen from the side its
// normals point to, and `tangent` is d position / d t (hasTangents = true).
//
// Quads are the square of half-extent `size` in the named plane, cut into
// sub-quads ((n1+1)*(n2+1) vertices; counts below 1 mean 1), flat = true.
// s runs 0..1 along the first named axis and t along the second:
//   QuadXY: plane Z = z, s with +x, t with +y, normal +Z, tangent +Y.
//   QuadXZ: plane Y = y, s with +x, t with +z, normal +Y, tangent +Z.
//   QuadYZ: plane X = x, s with +y, t with +z, normal +X, tangent +Z.
Mesh makeQuadXY(float z, float size, int nx = 1, int ny = 1);
Mesh makeQuadXZ(float y, float size, int nx = 1, int nz = 1);
Mesh makeQuadYZ(float x, float size, int ny = 1, int nz = 1);
// Sphere around the origin, poles on Y (north +Y). (slices+1)*(stacks+1)
// vertices: the seam column is duplicated so s reaches 1, each pole is a row
// of coincident vertices. s = (longitude + pi) / 2pi with longitude 0 at +Z
// and +pi/2 at +X (the seam faces -Z, s = .5 faces +Z); t = 0 at the south
// pole, 1 at the north pole. Tangent = d position / d latitude (unit, towards
// the north pole); at a pole, the limit along that vertex's meridian.
// 2*slices*(stacks-1) triangles (none degenerate); at least 3 slices, 2 stacks.
Mesh makeSphere(float radius = 1.f, int slices = 60, int stacks = 60);
// Torus around the Z axis, lying in the XY plane (glutSolidTorus): `outer` is
// the radius of the ring, `inner` that of the tube. s goes once around the ring
// from +X towards +Y (`rings` steps), t once around the tube starting at the
// outer equator, then up towards +Z (`sides` steps); (rings+1)*(sides+1)
// vertices, 2*rings*sides triangles, at least 3 of each. Tangent = d position / d t.
Mesh makeTorus(float outer = 1.f, float inner = .5f, int sides = 20, int rings = 40);
// Box centred on the origin with full extents dx, dy, dz: 24 vertices, 4 per
// face with that face's normal, s and t 0..1 on every face. Side faces have t
// up (+Y), as seen unfolded like a cube map; +Y has t towards -Z, -Y towards +Z.
Mesh makeBox(float dx = 2.f, float dy = 2.f, float dz = 2.f);

// Wavefront OBJ through tinyobjloader: v, vt, vn, faces; polygons become
// triangles. Corners without vn get their face's normal; vn are normalized.
// st is the vt as written (may leave 0..1); hasTangents = false. False + error
// (with tinyobjloader's reason and the path) on failure or when there are no
// faces; `out` is only written on success.
bool loadObj(const std::string& path, Mesh& out, std::string& error);

}  // namespace glimmer

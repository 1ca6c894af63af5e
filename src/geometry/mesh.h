// Shapes as plain vertex arrays, built on the CPU. The renderer uploads them;
// nothing here calls OpenGL.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
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
    // LinesAdjacency: 4 indices per line; TrianglesAdjacency: 6 per triangle
    // (v0, adj01, v1, adj12, v2, adj20); Patches: GL_PATCHES, the indices in
    // the order given (the patch size comes from the script's NumPatchVertices).
    enum class Primitive { Triangles, Lines, Points, LinesAdjacency, TrianglesAdjacency, Patches };
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
// Torus around the Z axis, lying in the XY plane: `outer` is the radius of
// the ring, `inner` that of the tube (GLIB writes them tube first, as
// glutSolidTorus does; geometry/shape_registry.cpp swaps them). s goes once around the ring
// from +X towards +Y (`rings` steps), t once around the tube starting at the
// outer equator, then up towards +Z (`sides` steps); (rings+1)*(sides+1)
// vertices, 2*rings*sides triangles, at least 3 of each. Tangent = d position / d t.
Mesh makeTorus(float outer = 1.f, float inner = .5f, int sides = 20, int rings = 40);
// Box centred on the origin with full extents dx, dy, dz: 24 vertices, 4 per
// face with that face's normal, s and t 0..1 on every face. Side faces have t
// up (+Y), as seen unfolded like a cube map; +Y has t towards -Z, -Y towards +Z.
Mesh makeBox(float dx = 2.f, float dy = 2.f, float dz = 2.f);

// ---- more of glman's shapes (shapes_more.cpp, teapot.cpp) --------------------
//
// Cylinder and cone stand on the XZ plane around the +Y axis, from y = 0 to
// y = h (glman's `Cylinder r h`, `Cone r h`, defaults [1 1]). Around the axis
// they follow makeSphere: longitude 0 at +Z, +pi/2 at +X, the seam at -Z and
// s = (longitude + pi) / 2pi (s = .5 faces +Z); t = y / h on the side.
// Tangent = d position / d t (unit: +Y on the cylinder, up the slant on the
// cone). Caps are separate vertices with the cap's flat normal, s and t taken
// from x and z like the box's faces: the top (+Y) s = .5 + x/2r, t = .5 - z/2r,
// tangent -Z; the bottom (-Y) s = .5 + x/2r, t = .5 + z/2r, tangent +Z.
// At least 3 slices.
// Cylinder: side 2*(slices+1) vertices and 2*slices triangles, two caps of
// slices+1 vertices (centre first) and slices triangles each: 4*slices triangles.
Mesh makeCylinder(float radius = 1.f, float height = 1.f, int slices = 40);
// Cone: bottom cap as the cylinder's, side slices+1 base vertices plus one apex
// vertex per slice (at the slice's middle longitude, s = (i + .5)/slices, t = 1,
// carrying the slanted normal there): slices side triangles, 2*slices in all.
// Side normals are (h sin lng, r, h cos lng) / sqrt(h^2 + r^2).
Mesh makeCone(float radius = 1.f, float height = 1.f, int slices = 40);
// Disk of the given radius in the z = 0 plane, normal +Z, tangent +Y,
// s = .5 + x/2r and t = .5 + y/2r, flat = true. Centre vertex then a ring of
// `slices` vertices starting at +X going towards +Y; `slices` triangles (at least 3).
Mesh makeDiskXY(float radius = 1.f, int slices = 40);
// The Newell teapot (glutSolidTeapot): the published 32 bicubic Bezier patches
// (teapot_data.h), each evaluated on a (subdivisions+1)^2 grid (at least 1):
// 32*(subdivisions+1)^2 vertices, 32*subdivisions^2*2 triangles, patch after
// patch in the published order (rim 4, body 8, handle 4, spout 4, lid 8,
// bottom 4). Patches are not welded; the triangles at the lid's and the
// bottom's centre rows (where a patch row collapses to one point) are
// degenerate but kept, so the counts stay regular. Y up, spout towards +X,
// handle towards -X, like glutSolidTeapot: position = size/2 * (x, z - 1.5, -y)
// of the Newell data (Z up), so size 1 spans y -0.75..0.825, a body radius of 1
// and about x -1.5..1.72. s runs along a patch row, t across the rows (0..1 on
// every patch); tangent = d position / d t (unit); normals from the partial
// derivatives (outward), falling back to a nearby parameter, and on the axis to
// the axis itself, where a patch edge collapses. hasTangents = true.
Mesh makeTeapot(float size = 1.f, int subdivisions = 10);
// The six faces of the cube of half-extent `size` around the origin, facing
// INWARD (a skybox seen from inside): 24 vertices (4 per face, normal towards
// the centre), 12 triangles, counter-clockwise seen from inside. On every face
// s and t run 0..1 with s to the right and t up as seen from the centre: the
// four walls have t = +Y (looking at +X, s goes towards +Z; at -Z, towards
// +X; at -X, towards -Z; at +Z, towards -X); the ceiling (+Y) has s +X,
// t +Z; the floor (-Y) s +X, t -Z. Tangent = the t direction.
Mesh makeQuadBox(float size = 1.f);

// ---- point clouds (shapes_more.cpp) -----------------------------------------
// Points meshes (indices 0..n-1), deterministic for a given seed on every
// platform (own PCG32, not std::rand). s, t = the position's x, y mapped from
// -size..size to 0..1; normal +Z.
// `count` points uniform in the cube [-size, size]^3 (count < 0 means 0).
Mesh makePointCloud(int count, float size = 1.f, std::uint32_t seed = 1);
// An n x n x n grid of cell centres filling [-size, size]^3 (cell edge 2size/n,
// x fastest then y then z), each moved by up to `jitter` half-cells along each
// axis (uniform): jitter 0 is the regular grid, 1 lets a point go anywhere in
// its cell (clamped to 0..1, so points never leave the cube). n^3 points.
Mesh makeJitterCloud(int n, float size = 1.f, float jitter = .5f, std::uint32_t seed = 1);

// ---- meshes from given points (shapes_more.cpp) -----------------------------
// `Triangles [x y z] [x y z] [x y z] ...`: one triangle per 3 points (extra
// points ignored), each with its own 3 vertices carrying the face normal
// (counter-clockwise in the given order; +Z when degenerate), st (0,0), (1,0),
// (0,1) and tangent = normalized(c - a). flat = all triangles in one plane.
Mesh makeTrianglesFrom(const std::vector<glm::vec3>& points);
// `LinesAdjacency [..] [..] [..] [..]`: LinesAdjacency primitive, one
// 4-vertex line per 4 points in order (extra points ignored); normal +Z,
// s = k/3 for the k-th point of its group, t = 0.
Mesh makeLinesAdjacency(const std::vector<glm::vec3>& points);

// glBegin primitive names (`glBegin prim`).
enum class ImmediatePrimitive {
    Points, Lines, LineStrip, LineLoop, Triangles, TriangleStrip, TriangleFan,
    Quads, QuadStrip, Polygon, Patches
};
// Case-insensitive, with or without a "GL_" prefix ("triangle_strip",
// "GL_TRIANGLE_STRIP"); nullopt for anything else.
std::optional<ImmediatePrimitive> parseImmediatePrimitive(std::string_view name);
// glBegin(prim) / glVertex... / glEnd as GL would assemble them: one vertex per
// glVertex, in order; indices make plain lists. Points -> Points; Lines,
// LineStrip, LineLoop -> Lines (strip: i,i+1; loop adds n-1,0); Triangles,
// TriangleStrip (GL's alternating order, so every triangle keeps the strip's
// facing), TriangleFan, Quads (a,b,c + a,c,d), QuadStrip (quad 2k,2k+1,2k+3,2k+2),
// Polygon (a fan from the first vertex) -> Triangles; Patches -> Patches with
// indices 0..n-1 as given. Incomplete trailing groups are dropped as GL does.
// Triangle vertices get the normalized sum of their triangles' area-weighted
// face normals (counter-clockwise = front); other vertices normal +Z. st = 0.
// flat = Triangles that all lie in one plane.
Mesh makeImmediate(ImmediatePrimitive primitive, const std::vector<glm::vec3>& points);

// ---- derived meshes (wire.cpp) -------------------------------------------------
// The unique edges of a Triangles mesh as a Lines mesh (Wire... variants).
// Vertices at the same position (within 1e-5 of the mesh's size, e.g. the
// box's face corners or a sphere's seam) are merged first, so an edge shared by
// two faces is drawn once; degenerate edges are dropped. Output vertices: one
// per merged position actually used, in order of first appearance, with the
// first vertex's st and tangent and the normalized mean of the merged normals.
// A box (2 triangles per face) gives 8 vertices and 18 edges. Anything but
// Triangles comes back empty (primitive Lines).
Mesh makeWire(const Mesh& solid);
// Triangles with adjacency for `ObjAdj`: the same vertices; per triangle
// (a, b, c) the indices a, adj(ab), b, adj(bc), c, adj(ca), where adj(xy) is
// the third vertex of the triangle across edge xy (found by position, so split
// vertices still connect; the neighbour running the edge in the opposite
// direction is preferred) and, on a boundary edge, the triangle's own
// opposite vertex. Primitive TrianglesAdjacency; anything but Triangles comes
// back empty.
Mesh makeObjAdjacency(const Mesh& triangles);

// Wavefront OBJ through tinyobjloader: v, vt, vn, faces; polygons become
// triangles. Corners without vn get their face's normal; vn are normalized.
// st is the vt as written (may leave 0..1); hasTangents = false. False + error
// (with tinyobjloader's reason and the path) on failure or when there are no
// faces; `out` is only written on success.
bool loadObj(const std::string& path, Mesh& out, std::string& error);
// What an OBJ asks for, counted in one pass over its text before
// tinyobjloader sees it (issue 30: a 100 MB file of faces took 4.1 GB, one
// face of a million corners never finished being cut into triangles).
struct ObjCounts {
    std::uint64_t positions = 0, texcoords = 0, normals = 0;  // v, vt, vn lines
    std::uint64_t triangles = 0;      // after each face is cut into corners - 2
    std::uint64_t cuttingWork = 0;    // the sum of corners^2 over faces of 5 corners or more
    std::uint64_t mostCorners = 0;    // of one face
    int mostCornersLine = 0;
    std::uint64_t bytes = 0;          // an upper estimate of what loading takes (tinyobjloader and the Mesh)
};
ObjCounts countObj(const std::string& text);
// loadObj from the file's text (already read and bounded) and its counts
// (countObj's, made once by a caller that checked them against a budget).
bool loadObjText(const std::string& text, const ObjCounts& counts, const std::string& path, Mesh& out,
                 std::string& error);
// tinyobjloader cuts a polygon into triangles in time that grows with the
// square of its corners: each face may have at most kMaxObjFaceCorners, and
// all faces of five corners or more together at most kMaxObjCuttingWork
// corners squared (about a second on one core).
constexpr std::uint64_t kMaxObjFaceCorners = 1000;
constexpr std::uint64_t kMaxObjCuttingWork = 100'000'000;

// The bytes a built mesh takes: its arrays on the CPU and their copy on the GPU.
std::uint64_t meshBytes(const Mesh& m);

}  // namespace glimmer

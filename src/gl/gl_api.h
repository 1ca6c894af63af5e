// The OpenGL entry points Glimmer calls, loaded at run time through the
// function the backend hands over (OSMesaGetProcAddress, eglGetProcAddress,
// glfwGetProcAddress).
//
// Why not call GL (or GLEW's pointers) directly: GL 1.1 entry points such as
// glClear are link-time symbols, and both libGL (glvnd, for EGL and GLX) and
// libOSMesa export them. One binary can bind each name to one library only,
// so one of the two backends would draw into nothing. GLEW also asks libGLX
// for addresses and fails under OSMesa. A table filled through the current
// backend's loader serves every backend with one code path.
#pragma once
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

#include "gl/proc_address.h"

namespace glimmer {

// Every function here is in OpenGL ES 3.0 (and so in WebGL 2) as well as in
// desktop OpenGL: the renderer's whole path on an ES context.
#define GLIMMER_GL_FUNCTIONS(X)                                                                          \
    X(GetError) X(GetString) X(GetIntegerv) X(Enable) X(Disable) X(Viewport) X(Clear) X(ClearColor)     \
    X(DepthFunc) X(DepthMask) X(ColorMask) X(Finish) X(Flush) X(ReadPixels) X(PixelStorei) X(LineWidth)             \
    X(GenTextures) X(DeleteTextures) X(BindTexture) X(TexImage2D) X(TexImage3D) X(TexParameteri)       \
    X(ActiveTexture) X(GenerateMipmap)                                                                   \
    X(DrawElements) X(DrawArrays)                                                                        \
    X(GenBuffers) X(DeleteBuffers) X(BindBuffer) X(BufferData)                                           \
    X(GetAttribLocation) X(BindAttribLocation) X(VertexAttribPointer) X(EnableVertexAttribArray) X(DisableVertexAttribArray)  \
    X(VertexAttrib4f)                                                                                    \
    X(CreateShader) X(DeleteShader) X(ShaderSource) X(CompileShader) X(GetShaderiv) X(GetShaderInfoLog) \
    X(CreateProgram) X(DeleteProgram) X(AttachShader) X(LinkProgram) X(GetProgramiv)                    \
    X(GetProgramInfoLog) X(UseProgram) X(GetUniformLocation) X(GetActiveUniform)                        \
    X(Uniform1i) X(Uniform1f) X(Uniform1fv) X(Uniform2fv) X(Uniform3fv) X(Uniform4fv) X(Uniform1iv)     \
    X(Uniform2iv) X(Uniform3iv) X(Uniform4iv) X(UniformMatrix2fv) X(UniformMatrix3fv)                   \
    X(UniformMatrix4fv)                                                                                  \
    X(GenFramebuffers) X(DeleteFramebuffers) X(BindFramebuffer) X(FramebufferTexture2D)                 \
    X(CheckFramebufferStatus) X(GenRenderbuffers) X(DeleteRenderbuffers) X(BindRenderbuffer)            \
    X(RenderbufferStorage) X(FramebufferRenderbuffer) X(DrawBuffers) X(ReadBuffer)                      \
    X(BlitFramebuffer) X(Scissor) X(GenVertexArrays) X(BindVertexArray) X(DeleteVertexArrays)           \
    X(GenQueries) X(DeleteQueries) X(BeginQuery) X(EndQuery)

// Desktop OpenGL only: the fixed-function state that feeds the compatibility
// built-ins, client arrays, whole-texture reads, GPU timer results,
// tessellation patches. Null on an OpenGL ES context (WebGL 2, EGL's ES
// API), where the renderer takes its ES path instead (GlApi::es).
#define GLIMMER_GL_DESKTOP_FUNCTIONS(X)                                                                  \
    X(ClearDepth) X(MatrixMode) X(LoadMatrixf) X(Color4f) X(PointSize) X(ShadeModel)                    \
    X(GetTexImage) X(ClientActiveTexture)                                                                \
    X(EnableClientState) X(DisableClientState) X(VertexPointer) X(NormalPointer) X(TexCoordPointer)     \
    X(Begin) X(End) X(TexCoord2f) X(Vertex2f) X(DrawBuffer)                                              \
    X(GetQueryObjectui64v) X(PatchParameteri) X(BindFragDataLocation)

struct GlApi {
#define GLIMMER_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
    GLIMMER_GL_FUNCTIONS(GLIMMER_GL_MEMBER)
    GLIMMER_GL_DESKTOP_FUNCTIONS(GLIMMER_GL_MEMBER)
#undef GLIMMER_GL_MEMBER
    // The context is OpenGL ES (its GL_VERSION begins "OpenGL ES"): the
    // desktop entries are null, whatever getProcAddress would hand out for
    // them (Mesa's EGL returns a stub for any name).
    bool es = false;
    // Set only on a context made to report resets (EGL's
    // LOSE_CONTEXT_ON_RESET, asked for by the GPU backends): a GPU shared by
    // several processes may reset the whole engine when one of them hangs
    // or is killed mid-draw, and an innocent context then reads back zeros
    // without an error. Null elsewhere (see contextFailure()).
    GLenum(GLAPIENTRY* GetGraphicsResetStatus)() = nullptr;
};


// Fills every entry: on desktop OpenGL all of them, on OpenGL ES the common
// ones. False, and the missing names in `error`, if any it needs is absent.
// Call with the context current (it reads GL_VERSION).
bool loadGlApi(GlApi& gl, const GetProcAddress& getProc, std::string& error);

// Why the context can no longer be trusted to have drawn what it was asked
// to, or "" when it can: a reset reported by the driver (guilty, innocent or
// unknown), GL_CONTEXT_LOST, or GL_OUT_OF_MEMORY (a texture or buffer the
// driver could not allocate draws as black). Drains glGetError; other errors
// are not failures of the machine: the first of them goes to `refused` when
// given (GL_NO_ERROR if none), for refusedCallWarning.
std::string contextFailure(const GlApi& gl, GLenum* refused = nullptr);

// The warning for a call the driver refused while drawing (an error
// glGetError held after the frame that is not a failure of the machine):
// the call did nothing, so a step of the picture may be missing. A script
// can cause one (two samplers of different types on one unit fail the
// draw), and so can a renderer bug; either way the picture is not all the
// script asked for, and a refused call is otherwise silent on llvmpipe and
// a console line in a browser's WebGL.
std::string refusedCallWarning(GLenum error);

}  // namespace glimmer

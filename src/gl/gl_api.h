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

#define GLIMMER_GL_FUNCTIONS(X)                                                                          \
    X(GetError) X(GetString) X(GetIntegerv) X(Enable) X(Disable) X(Viewport) X(Clear) X(ClearColor)     \
    X(ClearDepth) X(DepthFunc) X(DepthMask) X(Finish) X(Flush) X(ReadPixels) X(PixelStorei)             \
    X(MatrixMode) X(LoadMatrixf) X(Color4f) X(LineWidth) X(PointSize) X(ShadeModel)                     \
    X(GenTextures) X(DeleteTextures) X(BindTexture) X(TexImage2D) X(TexImage3D) X(TexParameteri) X(GetTexImage) \
    X(ActiveTexture) X(ClientActiveTexture) X(GenerateMipmap)                                                              \
    X(EnableClientState) X(DisableClientState) X(VertexPointer) X(NormalPointer) X(TexCoordPointer)     \
    X(DrawElements) X(DrawArrays) X(Begin) X(End) X(TexCoord2f) X(Vertex2f)                             \
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
    X(RenderbufferStorage) X(FramebufferRenderbuffer) X(DrawBuffers) X(DrawBuffer) X(ReadBuffer)        \
    X(BlitFramebuffer) X(Scissor) X(GenVertexArrays) X(BindVertexArray) X(DeleteVertexArrays)                      \
    X(GenQueries) X(DeleteQueries) X(BeginQuery) X(EndQuery) X(GetQueryObjectui64v) X(PatchParameteri)

struct GlApi {
#define GLIMMER_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
    GLIMMER_GL_FUNCTIONS(GLIMMER_GL_MEMBER)
#undef GLIMMER_GL_MEMBER
};


// Fills every entry; false and the missing names in `error` if any is absent.
bool loadGlApi(GlApi& gl, const GetProcAddress& getProc, std::string& error);

}  // namespace glimmer

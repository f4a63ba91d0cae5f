// Testbed renderer — the handful of OpenGL 1.x entry points the renderer uses,
// loaded at run time through the context's own GetProcAddress.
//
// Loading them instead of linking libGL keeps one renderer usable with both
// an OSMesa context (offscreen) and an SDL2/GLX context (window) in the same
// executable: libOSMesa and libGL both export gl* symbols, and a call bound
// to the wrong library would dispatch into the wrong context.
#pragma once

#include <GL/gl.h>

namespace tb {

/// Fixed-function OpenGL entry points (immediate mode).
struct GlApi {
    void(APIENTRY* Viewport)(GLint, GLint, GLsizei, GLsizei) = nullptr;
    void(APIENTRY* ClearColor)(GLclampf, GLclampf, GLclampf, GLclampf) = nullptr;
    void(APIENTRY* Clear)(GLbitfield) = nullptr;
    void(APIENTRY* MatrixMode)(GLenum) = nullptr;
    void(APIENTRY* LoadIdentity)() = nullptr;
    void(APIENTRY* Ortho)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble) = nullptr;
    void(APIENTRY* Enable)(GLenum) = nullptr;
    void(APIENTRY* Disable)(GLenum) = nullptr;
    void(APIENTRY* BlendFunc)(GLenum, GLenum) = nullptr;
    void(APIENTRY* LineWidth)(GLfloat) = nullptr;
    void(APIENTRY* Begin)(GLenum) = nullptr;
    void(APIENTRY* End)() = nullptr;
    void(APIENTRY* Vertex2f)(GLfloat, GLfloat) = nullptr;
    void(APIENTRY* Color4f)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
    void(APIENTRY* Finish)() = nullptr;
    void(APIENTRY* PixelStorei)(GLenum, GLint) = nullptr;
    void(APIENTRY* ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, GLvoid*) = nullptr;
    void(APIENTRY* ReadBuffer)(GLenum) = nullptr;
    GLenum(APIENTRY* GetError)() = nullptr;

    /// Resolves every entry point with `getProc`; returns false (and names the
    /// first missing function in `missing`) when one cannot be found.
    using GetProc = void* (*)(const char*);
    bool load(GetProc getProc, const char** missing = nullptr);
};

}  // namespace tb

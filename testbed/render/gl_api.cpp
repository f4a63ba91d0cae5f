// Testbed renderer — implementation of gl_api.hpp (see there).
#include "render/gl_api.hpp"

#include <cstring>

namespace tb {

namespace {
template <class F>
bool loadOne(F& fn, GlApi::GetProc getProc, const char* name, const char** missing) {
    void* p = getProc(name);
    if (!p) {
        if (missing) *missing = name;
        return false;
    }
    static_assert(sizeof(F) == sizeof(void*));
    std::memcpy(&fn, &p, sizeof(void*));
    return true;
}
}  // namespace

bool GlApi::load(GetProc getProc, const char** missing) {
    bool ok = true;
#define TBR_LOAD(name) ok = ok && loadOne(name, getProc, "gl" #name, missing)
    TBR_LOAD(Viewport);
    TBR_LOAD(ClearColor);
    TBR_LOAD(Clear);
    TBR_LOAD(MatrixMode);
    TBR_LOAD(LoadIdentity);
    TBR_LOAD(Ortho);
    TBR_LOAD(Enable);
    TBR_LOAD(Disable);
    TBR_LOAD(BlendFunc);
    TBR_LOAD(LineWidth);
    TBR_LOAD(Begin);
    TBR_LOAD(End);
    TBR_LOAD(Vertex2f);
    TBR_LOAD(Color4f);
    TBR_LOAD(Finish);
    TBR_LOAD(PixelStorei);
    TBR_LOAD(ReadPixels);
    TBR_LOAD(ReadBuffer);
    TBR_LOAD(GetError);
#undef TBR_LOAD
    return ok;
}

}  // namespace tb

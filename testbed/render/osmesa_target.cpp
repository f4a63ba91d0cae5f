// Testbed renderer — implementation of osmesa_target.hpp (see there).
#include "render/osmesa_target.hpp"

#include <GL/osmesa.h>

#include <cstring>
#include <stdexcept>

namespace tb {

struct OsmesaTarget::Impl {
    OSMesaContext context = nullptr;
    std::vector<std::uint8_t> buffer;
};

namespace {
void* osmesaProc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }
}  // namespace

OsmesaTarget::OsmesaTarget(int width, int height) : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw std::runtime_error("offscreen target: invalid size " + std::to_string(width) + "x" +
                                 std::to_string(height));
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_ACCUM_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_COMPAT_PROFILE,
                           0};
    impl_->context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!impl_->context) impl_->context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (!impl_->context) throw std::runtime_error("offscreen target: OSMesa could not create a context");
    impl_->buffer.resize(static_cast<std::size_t>(width) * height * 4);
    makeCurrent();
    const char* missing = nullptr;
    if (!gl_.load(&osmesaProc, &missing)) {
        OSMesaDestroyContext(impl_->context);
        impl_->context = nullptr;
        throw std::runtime_error(std::string("offscreen target: OSMesa lacks ") +
                                 (missing ? missing : "a GL function"));
    }
}

OsmesaTarget::~OsmesaTarget() {
    if (impl_ && impl_->context) OSMesaDestroyContext(impl_->context);
}

void OsmesaTarget::makeCurrent() {
    if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width_, height_))
        throw std::runtime_error("offscreen target: OSMesaMakeCurrent failed");
}

Image OsmesaTarget::readImage() {
    gl_.Finish();
    Image image;
    image.width = width_;
    image.height = height_;
    image.rgba = impl_->buffer;  // OSMesa's buffer has its first row at the bottom
    flipVertical(image);
    return image;
}

}  // namespace tb

#include "app/names.h"

namespace app {
namespace {

// The value among `values` whose library name is `name`.
template <class T, class Values, class NameOf>
bool parseByName(const std::string& name, const Values& values, NameOf nameOf, T& out) {
    for (T value : values)
        if (name == nameOf(value)) {
            out = value;
            return true;
        }
    return false;
}

}  // namespace

const std::vector<crowdgpu::Method>& allMethods() {
    using crowdgpu::Method;
    static const std::vector<Method> methods = {Method::VertexShader, Method::VertexShaderInstanced,
                                                Method::TwoPass,      Method::TwoPassDirect,
                                                Method::Compute,      Method::Static};
    return methods;
}

std::string methodList() {
    std::string list;
    for (crowdgpu::Method m : allMethods()) list += (list.empty() ? "" : ", ") + std::string(crowdgpu::methodName(m));
    return list;
}

bool parseMethod(const std::string& name, crowdgpu::Method& out) {
    return parseByName(name, allMethods(), crowdgpu::methodName, out);
}

bool parseCulling(const std::string& name, crowdgpu::Culling& out) {
    using crowdgpu::Culling;
    return parseByName(name, std::initializer_list<Culling>{Culling::Gpu, Culling::Cpu, Culling::Off}, crowdgpu::cullingName, out);
}

bool parseShadowRaster(const std::string& name, crowdgpu::ShadowRaster& out) {
    using crowdgpu::ShadowRaster;
    return parseByName(name, std::initializer_list<ShadowRaster>{ShadowRaster::Hardware, ShadowRaster::Compute},
                       crowdgpu::shadowRasterName, out);
}

bool parseAnimation(const std::string& name, crowdgpu::Animation& out) {
    using crowdgpu::Animation;
    return parseByName(name, std::initializer_list<Animation>{Animation::Gpu, Animation::Cpu}, crowdgpu::animationName, out);
}

bool parseBehaviour(const std::string& name, crowdgpu::Behaviour& out) {
    using crowdgpu::Behaviour;
    return parseByName(name, std::initializer_list<Behaviour>{Behaviour::InPlace, Behaviour::March, Behaviour::Mill}, crowdgpu::behaviourName, out);
}

}  // namespace app

#pragma once
// The vertex-shader methods: they produce nothing before the draw; the draw pass skins the bind pose
// while drawing (render/character_draw.h). "vs" is the paper's baseline, one draw per character with
// its bones at a dynamic uniform offset (the paper's constant registers); "vs-instanced" is the
// modern one, one instanced draw per (model, LOD) bucket with the bones in a storage buffer.
#include "skin/skinning_method.h"

namespace skin {

class VertexShaderSkinning final : public SkinningMethod {
public:
    explicit VertexShaderSkinning(bool instanced) : instanced_(instanced) {}
    Method method() const override { return instanced_ ? Method::VertexShaderInstanced : Method::VertexShader; }
    render::DrawInput drawInput() const override {
        return instanced_ ? render::DrawInput::BindPoseInstanced : render::DrawInput::BindPosePerCharacter;
    }

private:
    bool instanced_;
};

}  // namespace skin

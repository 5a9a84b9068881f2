// What the renderer draws with, owned once for all its views (Filament's
// Engine): the shader programs and the flags they were built for, the
// water grid, the world's meshes and sky cubemap, the caustics map every
// view redraws, and the frame uniform buffers. Which of them a scene change
// rebuilds is decided in render/scene_update.h. Library-internal.
#pragma once

#include "render/caustics_map.h"
#include "render/contact_map.h"
#include "render/gpu/blocks.h"
#include "render/programs.h"
#include "render/telemetry.h"
#include "render/water_grid.h"
#include "render/water_visibility.h"
#include "render/world.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"
#include "swell/scene/grid.h"

#include <array>

namespace swell::detail {

// The uniform buffer of each kind of pass (Resources::frameUbo).
// PassProbe: the frame's water queries (render/surface_probe.h);
// PassContact: the contact foam's map (render/contact_map.h).
enum Pass {
    PassReflection = 0,
    PassRefraction = 1,
    PassMain = 2,
    PassWaterline = 3,
    PassProbe = 4,
    PassContact = 5,
    PassCount = 6
};

class Resources {
public:
    // shaders: where the programs' sources come from; omittedWaterTerms:
    // the water shading terms left out (swell/debug.h).
    Resources(gl::ShaderSources shaders, unsigned omittedWaterTerms);

    // Uploads a pass's frame uniforms into its buffer and binds it.
    void bindFrame(Pass pass, const FrameUniforms& f) const;

    // The water grid for the scene's grid settings and camera.
    void buildGrid(const Scene& scene);
    // The vertices the grid has (the water's vertex capture writes them all).
    int waterVertexCount() const { return (gridShape.cells + 1) * (gridShape.cells + 1); }

    gl::ShaderSources sources;
    // Water shading terms left out, for the benchmark (swell/debug.h).
    unsigned omittedWaterTerms = 0;
    Programs programs; // and the flags they were built for
    gl::VertexArray emptyVao;
    GridShape gridShape;
    WaterGrid waterGrid;
    // The water's vertices as its visibility pass drew them (render/water_visibility.h).
    WaterVertexCache waterVertexCache;
    // Whether the water is drawn in two passes where it can be: when this
    // GL can (vertexShadersStoreBuffers()) and the renderer was not asked
    // for one pass (RendererTesting::setWaterInTwoPasses).
    bool waterInTwoPasses = false;
    World world;
    SceneShapes shapes; // what the world's rigid bodies are built from (the assets' CPU data)
    // The sea floor: the scene's seabed, its island and the host's heights.
    std::shared_ptr<const Seabed> seabed = std::make_shared<const Seabed>();
    // The sun's light under the water, drawn again by each view that needs it (caustics_map.h).
    CausticsMap caustics;
    // Where solid geometry meets the water, drawn again by each view that
    // may show it (contact_map.h).
    ContactMap contact;

private:
    std::array<gl::Buffer, PassCount> frameUbo_;
};

} // namespace swell::detail

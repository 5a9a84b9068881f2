// Where C++ and GLSL meet: the binding points of the uniform blocks and
// shader storage buffers, the texture and image units, and the sizes of the
// compute passes' workgroups, fixed so that every program agrees without
// queries. Included by C++ and GLSL alike, so it holds only preprocessor
// lines and comments; every value has its reason above it.
#ifndef SWELL_GPU_BINDINGS_H
#define SWELL_GPU_BINDINGS_H

// Uniform blocks (their layouts: src/render/gpu/blocks.h and each wave
// model's own, generated into GLSL at build time).
#define SWELL_BINDING_FRAME 0
// The wave model's first uniform block (each model documents its own).
#define SWELL_BINDING_OCEAN 1
// The wake field's block (shaders/wake.glsl): where its cells lie.
#define SWELL_BINDING_WAKE 2
// The surface sources' parameters (swell/surface_source.h): the
// SurfaceSources block of the renderer's generated surface_sources.glsl.
#define SWELL_BINDING_SURFACE_SOURCES 3
// The caustics map's place (the Caustics block of caustics.glsl).
#define SWELL_BINDING_CAUSTICS 4
// The cloud shadow map's place (the CloudShadow block of cloud_shadow.glsl).
#define SWELL_BINDING_CLOUD_SHADOW 5
// The coast field's block (shaders/coast_field.glsl): where its samples lie,
// and the trains a wave model hands it in place of its own longest waves.
#define SWELL_BINDING_COAST 6

// Texture units.
#define SWELL_UNIT_SKY 0
#define SWELL_UNIT_REFLECTION_COLOR 1
#define SWELL_UNIT_REFLECTION_DEPTH 2
#define SWELL_UNIT_REFRACTION_COLOR 3
#define SWELL_UNIT_REFRACTION_DEPTH 4
// The wave model's textures (each model documents its own).
#define SWELL_UNIT_OCEAN0 6
#define SWELL_UNIT_OCEAN1 7
#define SWELL_UNIT_OCEAN2 8
#define SWELL_UNIT_OCEAN3 9
// The waterline mask: which pixels look out from below the water (underwater.glsl).
#define SWELL_UNIT_WATERLINE 10
// The image a post-process (FXAA) reads.
#define SWELL_UNIT_POST_SOURCE 11
// The wake field's frame (shaders/wake.glsl): height, slopes and foam per cell.
#define SWELL_UNIT_WAKE 12
// A copy of the host's depth (Renderer::draw's underwater pass over the host's geometry).
#define SWELL_UNIT_HOST_DEPTH 13
// The level a mip chain's compute pass reads (shaders/mip_downsample.comp),
// and the second chain's source of its software rasteriser's pass
// (shaders/mip_blocks.comp), which builds two chains in the same dispatches.
#define SWELL_UNIT_DOWNSAMPLE_SOURCE 14
#define SWELL_UNIT_DOWNSAMPLE_SOURCE_B 17
// The physical sky's tables (swell/scene/atmosphere.h), read by its bake only.
#define SWELL_UNIT_SKY_TRANSMITTANCE 14
#define SWELL_UNIT_SKY_MULTISCATTER 15
// The caustics map (caustics.glsl).
#define SWELL_UNIT_CAUSTICS 16
// The cloud layer's shadow map (cloud_shadow.glsl).
#define SWELL_UNIT_CLOUD_SHADOW 20
// The water's visibility pass's results that its shading pass reads
// (shaders/water_deferred.glsl, render/water_visibility.h): the triangle
// each pixel shows, and the depth the pass left.
#define SWELL_UNIT_WATER_VISIBILITY 5
#define SWELL_UNIT_WATER_DEPTH 23
// The temporal resolve (shaders/temporal_resolve.frag, render/temporal_resolve.h):
// the main pass's depth and the accumulated history it reads (the frame's
// colour: SWELL_UNIT_POST_SOURCE), and the clip box per drawn pixel (its
// centre and the pixel's water mark; its half extent and the pixel's
// depth), gathered at the drawn size by shaders/temporal_neighbourhood.frag.
#define SWELL_UNIT_TEMPORAL_DEPTH 18
#define SWELL_UNIT_TEMPORAL_HISTORY 19
#define SWELL_UNIT_TEMPORAL_BOX_CENTRE 21
#define SWELL_UNIT_TEMPORAL_BOX_EXTENT 22
// The coast field's texels (shaders/coast_field.glsl, swell/coast_field.h):
// each coast wave's layer, and what every wave shares. Their own units, not
// a wave model's, since every model reads them.
#define SWELL_UNIT_COAST_WAVES 24
#define SWELL_UNIT_COAST_COMMON 25
// The contact foam's map (shaders/contact.glsl, render/contact_map.h): the
// distance from each texel to where solid geometry meets the water; and the
// depth its pass drew, which the distance's first pass reads.
#define SWELL_UNIT_CONTACT 26
#define SWELL_UNIT_CONTACT_SOURCE 27

// Image units of the spectral model's compute passes (src/ocean/spectral/,
// shaders/ocean/spectral_fft.comp and spectral_foam.comp): the initial
// spectra and their frequencies the row pass reads, the two fields the
// passes transform in place, the slopes the column pass writes for
// shading, and the foam the foam step reads and writes (a pass of its own,
// so it shares the slopes' unit).
#define SWELL_IMAGE_SPECTRAL_INITIAL 0
#define SWELL_IMAGE_SPECTRAL_OMEGA 1
#define SWELL_IMAGE_SPECTRAL_DISPLACEMENT 2
#define SWELL_IMAGE_SPECTRAL_DERIVATIVES 3
#define SWELL_IMAGE_SPECTRAL_SLOPES 4
#define SWELL_IMAGE_SPECTRAL_FOAM 4
// The contact map's distance passes (shaders/contact_distance.comp): the
// image each pass writes (the rows' distances, then the map's).
#define SWELL_IMAGE_CONTACT_OUT 0

// Shader storage bindings: the frame's water queries' points and answers
// (shaders/surface_probe.comp), the caustics pass's refracted grid and its
// slices' triangles (caustics_sources.comp, caustics_images.comp), and the
// spray's clumps, the list of the living, the commands of the streaks'
// dispatch and draw (which the list writes) and the streaks
// (src/render/spray_passes.cpp).
#define SWELL_STORAGE_PROBE_QUERIES 0
#define SWELL_STORAGE_PROBE_ANSWERS 1
#define SWELL_STORAGE_CAUSTICS_SOURCES 2
#define SWELL_STORAGE_CAUSTICS_IMAGES 3
#define SWELL_STORAGE_SPRAY_CLUMPS 4
#define SWELL_STORAGE_SPRAY_LIST 5
#define SWELL_STORAGE_SPRAY_COMMANDS 6
#define SWELL_STORAGE_SPRAY_STREAKS 7
// The water's vertices as its visibility pass drew them, and the grid's
// index buffer, which its shading pass reads (shaders/water_vertex_cache.glsl).
#define SWELL_STORAGE_WATER_VERTICES 8
#define SWELL_STORAGE_WATER_INDICES 9
// The screen tiles that show water, which the water's shading pass draws
// (shaders/water_tiles.comp, water_tiles.vert): its indirect draw command,
// then each tile's place.
#define SWELL_STORAGE_WATER_TILES 10
// The water's vertices at the view's previous draw, for the host's motion
// vectors (shaders/water_previous.vert writes them, water_motion.vert reads them).
#define SWELL_STORAGE_WATER_PREVIOUS 11

// Workgroups.
// The frame's water queries: the side of each answer's block of drawn
// vertices, one 64-invocation workgroup. 8 x 8 vertices hold 3 rings of
// cells round the cell the search starts from (the drawn triangle lies in
// the first ring but where the filtered waves move it further).
#define SWELL_PROBE_BLOCK 8
// The caustics pass's compute steps.
#define SWELL_CAUSTICS_GROUP 64
// The spray's passes: spray_clumps.comp evaluates every slot's clump in
// workgroups of SWELL_SPRAY_GROUP, spray_list.comp lists the living ones
// in one workgroup of SWELL_SPRAY_LIST_GROUP, spray_streaks.comp
// evaluates each living clump's streaks (workgroups of SWELL_SPRAY_GROUP).
#define SWELL_SPRAY_GROUP 64
#define SWELL_SPRAY_LIST_GROUP 256
// The water's shading pass draws the screen in square tiles of this many
// pixels a side, only those that show water (shaders/water_tiles.comp): a
// tile is one workgroup of the pass that lists them. 8 leaves about 1% of
// the shaded pixels outside the water at 1280 x 720 (the tiles along the
// horizon and round the world's objects).
#define SWELL_WATER_TILE 8
// The spectral model's foam step (spectral_foam.comp): a square tile of
// texels, each invocation one texel of every image it writes.
#define SWELL_FOAM_STEP_GROUP 16
// A mip chain's compute pass: how many levels one of its dispatches
// writes: a workgroup of 2^(n-1) x 2^(n-1) invocations reduces a 2^n x 2^n
// block in shared memory (mip_downsample.comp) ...
#define SWELL_DOWNSAMPLE_LEVELS 5
// ... and how many a dispatch of its software rasteriser's pass writes
// (mip_blocks.comp), where each invocation reduces a 2^n x 2^n block, in
// square workgroups of this side.
#define SWELL_DOWNSAMPLE_BLOCK_LEVELS 4
#define SWELL_DOWNSAMPLE_BLOCKS_GROUP 8

#endif

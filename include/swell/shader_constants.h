// Constants shared by C++ and GLSL. This file is included by both, so it holds
// only preprocessor lines and comments. Every value has its reason above it.
#ifndef SWELL_SHADER_CONSTANTS_H
#define SWELL_SHADER_CONSTANTS_H

// Most Gerstner waves summed per vertex. 64 keeps the wave UBO at 2 KiB
// (two vec4 per wave) and the vertex shader affordable on software GL.
#define SWELL_MAX_WAVES 64

// Snap levels of the LOD grid: level l snaps vertices to multiples of
// (finest step * 2^l). 24 levels span 0.1 m to over 800 km.
#define SWELL_GRID_LEVELS 24
// Boxes that bound the world's geometry for the reflection ray march; a
// scene with more objects marches every ray.
#define SWELL_MAX_WORLD_BOXES 16

// Uniform block binding points, fixed so every program agrees without queries.
#define SWELL_BINDING_FRAME 0
// The wave model's first uniform block (each model documents its own).
#define SWELL_BINDING_OCEAN 1

// The spectral model (src/ocean/spectral/): cascades of SWELL_FFT_SIZE^2
// samples, each a periodic patch of its own size. 256 resolves a patch's
// waves down to 4 texels per wavelength with one 64-thread workgroup per
// line of the FFT (spectral_fft.comp takes its stages two at a time, so the
// size is a power of 4); 4 cascades span 1 km down to about 5 cm.
#define SWELL_FFT_SIZE 256
#define SWELL_FFT_LOG2_SIZE 8
#define SWELL_FFT_CASCADES 4
// Sinusoids in each cascade's anti-tiling warp (src/ocean/spectral/
// spectral_warp.h): enough directions that every wave direction and every
// shift is decorrelated, few enough to cost little per vertex and pixel.
#define SWELL_FFT_WARP_WAVES 6
// The water's pixels take each cascade's warp (its lookup point and
// Jacobian) interpolated from the grid's vertices where a grid cell is at
// most 1/SWELL_FFT_WARP_CELLS_PER_WAVELENGTH of the warp's shortest
// sinusoid, and evaluate it themselves elsewhere: a sinusoid sampled 20
// times a wavelength is off its linear interpolation by at most
// (pi/20)^2/2 = 1.2% of its amplitude, a fraction of a texel of the
// lookup (docs/RENDERING.md, "The spectral ocean").
#define SWELL_FFT_WARP_CELLS_PER_WAVELENGTH 20
// The spectral model's whitecap foam lives in the world, not in the periodic
// cascades (whose foam would repeat with their patches): SWELL_FOAM_LEVELS
// camera-following windows of SWELL_FOAM_SIZE^2 texels, each level's texels
// SWELL_FOAM_LEVEL_RATIO times the last's (src/ocean/spectral/world_foam.h).
#define SWELL_FOAM_SIZE 256
#define SWELL_FOAM_LOG2_SIZE 8
#define SWELL_FOAM_LEVELS 2
#define SWELL_FOAM_LEVEL_RATIO 4.0
// The whitecaps' texture (src/ocean/spectral/foam_texture.h): octaves of
// gradient noise on lattices turned from each other, plus one that warps
// them; each lattice repeats after SWELL_FOAM_NOISE_PERIOD cells (14 km for
// the coarsest octave, 140 m for the finest: more than a picture holds
// where the octave is not faded into its mean; a float still holds a cell
// index that large to a two-thousandth of a cell).
#define SWELL_FOAM_OCTAVES 6
#define SWELL_FOAM_NOISE_MAPS 7
#define SWELL_FOAM_NOISE_PERIOD 4096

// Texture units, fixed for the same reason.
#define SWELL_UNIT_SKY 0
#define SWELL_UNIT_REFLECTION_COLOR 1
#define SWELL_UNIT_REFLECTION_DEPTH 2
#define SWELL_UNIT_REFRACTION_COLOR 3
#define SWELL_UNIT_REFRACTION_DEPTH 4
#define SWELL_UNIT_BASE_COLOR 5
// The wave model's textures (each model documents its own).
#define SWELL_UNIT_OCEAN0 6
#define SWELL_UNIT_OCEAN1 7
#define SWELL_UNIT_OCEAN2 8
#define SWELL_UNIT_OCEAN3 9
// The waterline mask: which pixels look out from below the water (underwater.glsl).
#define SWELL_UNIT_WATERLINE 10

// Values of the waterline mask (an R8 texture): the pixel's ray meets no
// water, meets it first from above, or first from below.
#define SWELL_WATERLINE_NO_HIT 0.0
#define SWELL_WATERLINE_ABOVE 0.5
#define SWELL_WATERLINE_BELOW 1.0

// Refractive index of sea water for visible light (air: 1). 1.333 is pure
// water's at 589 nm and 20 C; sea water's is about 1.34 (Quan and Fry 1995).
// Snell's window's half-angle is asin(1 / n): 48.6 degrees.
#define SWELL_WATER_IOR 1.333
// The image a post-process (FXAA) reads.
#define SWELL_UNIT_POST_SOURCE 11
// The wake field's frame (shaders/wake.glsl): height, slopes and foam per cell.
#define SWELL_UNIT_WAKE 12
// A copy of the host's depth (Renderer::draw's underwater pass over the host's geometry).
#define SWELL_UNIT_HOST_DEPTH 13
// The level a mip chain's compute pass reads (shaders/mip_downsample.comp),
// and how many levels one of its dispatches writes: a workgroup of
// 2^(n-1) x 2^(n-1) invocations reduces a 2^n x 2^n block in shared memory.
#define SWELL_UNIT_DOWNSAMPLE_SOURCE 14
#define SWELL_DOWNSAMPLE_LEVELS 5
// ...and how many levels a dispatch of its software rasteriser's pass
// writes (shaders/mip_blocks.comp): each invocation reduces a 2^n x 2^n
// block. That pass builds two chains in the same dispatches; the second's
// source is read from this unit.
#define SWELL_DOWNSAMPLE_BLOCK_LEVELS 4
#define SWELL_UNIT_DOWNSAMPLE_SOURCE_B 17
// ...and its uniform block: where the cells lie.
#define SWELL_BINDING_WAKE 2
// Surface sources (swell/surface_source.h): the WaveSources block of
// shaders/surface_sources.glsl's generated code, four vec4 parameters a source;
// at most SWELL_MAX_SURFACE_SOURCES sources, the wake's included.
#define SWELL_BINDING_SURFACE_SOURCES 3
#define SWELL_MAX_SURFACE_SOURCES 8
// The frame's water queries answered on the GPU (shaders/surface_probe.comp):
// shader storage bindings of the query points and the answers, and the side
// of each answer's block of drawn vertices. 8 x 8 vertices hold 3 rings of
// cells round the cell the search starts from (the drawn triangle lies in
// the first ring but where the filtered waves move it further), and are one
// 64-invocation workgroup.
#define SWELL_STORAGE_PROBE_QUERIES 0
#define SWELL_STORAGE_PROBE_ANSWERS 1
#define SWELL_PROBE_BLOCK 8
// The surface sources' foam (the bodies' wake's) fades as exp(-age / this),
// s: the spectral whitecaps' default lifetime (salt water, Monahan &
// O'Muircheartaigh 1980). The shading draws source foam above
// exp(-1 s / this) as a breaking's own (the whitecaps' dense layer).
#define SWELL_SOURCE_FOAM_LIFETIME_S 3.85

// A wave is faded out where the grid samples it with fewer than this many
// cells per wavelength (Nyquist is 2; a little more keeps shading stable).
#define SWELL_MIN_CELLS_PER_WAVELENGTH 2.0
// ...and is at full strength from this many cells per wavelength on.
#define SWELL_FULL_CELLS_PER_WAVELENGTH 4.0

// Debug views, selected by the scene or viewer (prepended as SWELL_DEBUG_VIEW).
#define SWELL_VIEW_SHADED 0
#define SWELL_VIEW_NORMALS 1
#define SWELL_VIEW_REFLECTION 2
#define SWELL_VIEW_REFRACTION 3
#define SWELL_VIEW_LOD 4
#define SWELL_VIEW_WIREFRAME 5
#define SWELL_VIEW_FOAM 6

// The label pass (swell/labels.h, shaders/labels.glsl; prepended as
// SWELL_LABEL_PASS 1 in its programs): each pixel's semantic class. The
// classes of scene objects follow from SWELL_LABEL_FIRST_OBJECT_CLASS on,
// one per distinct class name in the scene (FrameLabels::classes).
#define SWELL_LABEL_NONE 0
#define SWELL_LABEL_SKY 1
#define SWELL_LABEL_WATER 2
#define SWELL_LABEL_WHITECAP_FOAM 3
#define SWELL_LABEL_WAKE_FOAM 4
#define SWELL_LABEL_TERRAIN 5
#define SWELL_LABEL_FIRST_OBJECT_CLASS 16
// A water pixel is labelled foam where foam covers at least this share of it.
#define SWELL_LABEL_FOAM_COVER 0.5

// Reflection lookups (prepended as SWELL_REFLECTION_MODE).
#define SWELL_REFLECTION_FIXED 0
#define SWELL_REFLECTION_RAYMARCH 1

// Terms of the water shading (bit flags). The benchmark leaves one out at a
// time to measure what each costs (prepended as SWELL_OMITTED_TERMS, 0 in
// every normal build). Left out, a term becomes its cheapest stand-in:
// wave normals -> the interpolated vertex normal (and no foam, which the same
// per-pixel evaluation returns); reflection -> the sky's horizon colour;
// refraction -> the deep water colour; lighting -> no sun diffuse or
// specular; foam -> none; fog -> none; subsurface (light through the
// crests) -> none; filtering (normals filtered by the pixel's footprint,
// the highlight spread by what they leave out) -> every wave in the normal,
// unspread, as shading without horizon filtering would do.
#define SWELL_TERM_WAVE_NORMALS 1
#define SWELL_TERM_REFLECTION 2
#define SWELL_TERM_REFRACTION 4
#define SWELL_TERM_LIGHTING 8
#define SWELL_TERM_FOAM 16
#define SWELL_TERM_FOG 32
#define SWELL_TERM_SUBSURFACE 64
#define SWELL_TERM_FILTERING 128
#define SWELL_TERM_ALL 255

// Grid layouts (prepended as SWELL_GRID_LAYOUT; see shaders/grid.glsl).
#define SWELL_GRID_GEOMETRIC 0
#define SWELL_GRID_PAPER 1

// The physical sky (swell/atmosphere.h, src/core/atmosphere.cpp and
// shaders/atmosphere.glsl share these; docs/RENDERING.md). Lengths in m,
// coefficients in 1/m, for the three wavelengths drawn as red, green and
// blue: 680, 550 and 440 nm (Bruneton 2017's RGB wavelengths).
// The Earth and the top of its atmosphere (Bruneton 2017's Earth).
#define SWELL_ATMOSPHERE_BOTTOM_RADIUS_M 6360000.0
#define SWELL_ATMOSPHERE_TOP_RADIUS_M 6420000.0
// The eye's altitude for the baked sky, m: a deck's height (the sky hardly
// changes over the first hundred metres).
#define SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M 10.0
// Rayleigh scattering at sea level, 1.24062e-6 / lambda^4 (lambda in um)
// (Bruneton 2017; the same figures in Hillaire 2020, sec. 4), and its
// scale height (Bruneton & Neyret 2008, sec. 2.1).
#define SWELL_RAYLEIGH_SCATTERING_R 5.802e-6
#define SWELL_RAYLEIGH_SCATTERING_G 13.558e-6
#define SWELL_RAYLEIGH_SCATTERING_B 33.1e-6
#define SWELL_RAYLEIGH_SCALE_HEIGHT_M 8000.0
// Aerosols (Mie): Bruneton 2017's Angstrom beta 5.328e-3 over the scale
// height (alpha 0: grey), single-scattering albedo 0.9, so extinction
// 4.44e-6 and scattering 3.996e-6; Cornette-Shanks asymmetry g = 0.8.
#define SWELL_MIE_EXTINCTION 4.44e-6
#define SWELL_MIE_SCATTERING 3.996e-6
#define SWELL_MIE_SCALE_HEIGHT_M 1200.0
#define SWELL_MIE_ASYMMETRY 0.8
// Ozone absorbs (it does not scatter): its peak coefficient (Hillaire 2020,
// sec. 4), in a tent profile 1 at 25 km falling to 0 at 10 and 40 km
// (Bruneton 2017's two linear layers).
#define SWELL_OZONE_ABSORPTION_R 0.650e-6
#define SWELL_OZONE_ABSORPTION_G 1.881e-6
#define SWELL_OZONE_ABSORPTION_B 0.085e-6
#define SWELL_OZONE_PEAK_ALTITUDE_M 25000.0
#define SWELL_OZONE_HALF_WIDTH_M 15000.0
// Steps of the sky's ray march, spaced quadratically (dense near the eye,
// where the air is densest along a low ray): 40 keep the horizon's radiance
// within 1% of a 4000-step march (tests/cpu/test_atmosphere.cpp).
#define SWELL_SKY_MARCH_STEPS 40
// The transmittance table: (view zenith, altitude) texels, in Bruneton
// 2017's parametrisation (dense towards the horizon).
#define SWELL_TRANSMITTANCE_MU_SIZE 256
#define SWELL_TRANSMITTANCE_R_SIZE 64
// Hillaire 2020's multiple-scattering table (sec. 5.5): (sun zenith
// cosine, altitude), 32 x 32 as in the paper, in layers: Psi_ms, then the
// three order-2 harmonics of the air's share (swell/atmosphere.h).
#define SWELL_MULTISCATTER_SIZE 32
#define SWELL_MULTISCATTER_LAYERS 4
// Their texture units (the physical sky's bake only).
#define SWELL_UNIT_SKY_TRANSMITTANCE 14
#define SWELL_UNIT_SKY_MULTISCATTER 15

// The cloud layer (swell/clouds.h, src/core/clouds.cpp and shaders/clouds.glsl
// share these; docs/RENDERING.md, "Clouds"). A thin layer at an altitude,
// baked into the physical sky's cubemap with it.
// Octaves of gradient noise in its fractal sum: the coarsest cell is the
// scene's clouds.scale_m, the finest 1/32 of it (about 90 m for 3 km: finer
// than a texel of the bake straight up at 1.5 km is wide, 9 m, is lost anyway
// at the usual views, which look at the layer kilometres away).
#define SWELL_CLOUD_OCTAVES 6
// Standard deviation of the unfiltered fractal sum (measured over 10^6
// points by tests/cpu/test_clouds.cpp): a threshold at its quantile makes
// the clouded share of the layer the scene's cover.
#define SWELL_CLOUD_FBM_SIGMA 0.2491
// Softness of a cloud's edge, in units of that standard deviation: wide
// enough that a bake texel never steps from clear to opaque, narrow enough
// that edges read as edges.
#define SWELL_CLOUD_EDGE_SIGMA 0.12
// How far the domain warp moves a point, in coarsest cells (Quilez's domain
// warping): bends the lattice's straight runs into the swirls of real decks.
#define SWELL_CLOUD_WARP_CELLS 0.7
// The layer's shapes are drawn out along x this much (rolls and bands of a
// wind-driven deck).
#define SWELL_CLOUD_STRETCH 1.6
// Henyey-Greenstein asymmetry of cloud droplets in visible light: about
// 0.85 (Bohren 1987; Liou 2002, sec. 5.3): strongly forward.
#define SWELL_CLOUD_ASYMMETRY 0.85
// Angular width of the sky bake's texel, rad (90 degrees over 256): the
// footprint below which the layer's octaves are averaged away.
#define SWELL_CLOUD_TEXEL_RAD 0.00614
// The layer's shadows on the sea and the world (shaders/cloud_shadow.glsl,
// src/render/cloud_shadow_map.h): its transmittance along the sun's ray,
// baked per point of the sea's mean level into a camera-following map
// (R32F, mipmapped: the mip chain averages the transmittance itself, as a
// pixel's footprint does) when the sky or the sun changes or the camera
// has moved SWELL_CLOUD_SHADOW_REBAKE of the map's side from its centre.
// 16 km across: the sea to the haze from a boat, the horizon's first
// kilometres from a mast; 512 texels of 31 m, under the finest octave of
// a 3 km layer (94 m) and about the penumbra of a cloud 3 km up (the
// sun's 0.53 degrees: 28 m). Beyond it, the map's mean.
#define SWELL_CLOUD_SHADOW_EXTENT_M 16000.0
#define SWELL_CLOUD_SHADOW_SIZE 512
#define SWELL_CLOUD_SHADOW_REBAKE 0.125
// The lowest sun the shadows are cast for (sin of 2.9 degrees): a lower
// one's ray crosses the layer tens of kilometres away, and the air has
// dimmed its light to little anyway.
#define SWELL_CLOUD_SHADOW_MIN_SUN_Y 0.05
// The map's texture unit and uniform block (the CloudShadow block of cloud_shadow.glsl).
#define SWELL_UNIT_CLOUD_SHADOW 20
#define SWELL_BINDING_CLOUD_SHADOW 5

// Caustics (shaders/caustics.glsl, src/render/caustics_map.h): the sun's
// light refracted by the drawn surface onto horizontal slices under it,
// splatted with additive blending into a camera-following map.
// The map's side, m, and its texels per side: 48 m around the camera holds
// what a view under or near the water shows in detail; 512 texels of 9.4 cm
// resolve the focusing of the waves the source grid holds.
#define SWELL_CAUSTICS_EXTENT_M 48.0
#define SWELL_CAUSTICS_SIZE 512
// Source grid cells per side (the surface refracted): about 0.24 m cells over
// the map and its margins, so waves down to 0.5 m (SWELL_MIN_CELLS_PER_WAVELENGTH
// cells) focus the light; each is refracted once for every slice. On
// llvmpipe (2 shared cores, swell bench --still of docs/images/caustics.toml
// at 960x540) the pass took a median 655 ms a frame with 384 cells (0.16 m)
// and 459 ms with 256, whose net on the floor still shows every strand.
#define SWELL_CAUSTICS_CELLS 256
// Depth slices of the map: the pattern changes with depth as the waves'
// focal lengths are passed (a refracting surface of radius R focuses at
// n R / (n - 1), about 4 R in water: Hecht, "Optics", eq. 5.8); 3 slices, their depths in
// render/caustics_map.h, and the depths between interpolated.
#define SWELL_CAUSTICS_SLICES 3
// The sun's angular diameter, rad (0.53 deg, Allen's Astrophysical
// Quantities): no focus is sharper than the sun's disc seen from the floor.
#define SWELL_SUN_ANGULAR_DIAMETER_RAD 0.00925
// The caustics map's texture unit and uniform block (the Caustics block of caustics.glsl).
#define SWELL_UNIT_CAUSTICS 16
#define SWELL_BINDING_CAUSTICS 4
// The caustics pass's compute steps (caustics_sources.comp, caustics_images.comp):
// their workgroups' size, the shader storage bindings of the refracted grid
// and of the slices' triangles, and the odd stride of the triangles' draw
// order (slot = triangle * stride modulo the triangles, a permutation while
// their count, 2 * SWELL_CAUSTICS_CELLS^2, is a power of two: about 0.31 of
// it, so the triangles drawn in turn lie far apart in the grid).
#define SWELL_CAUSTICS_GROUP 64
#define SWELL_STORAGE_CAUSTICS_SOURCES 2
#define SWELL_STORAGE_CAUSTICS_IMAGES 3
#define SWELL_CAUSTICS_ORDER_STRIDE 40503

// Shafts of light (shaders/light_shafts.glsl, src/render/light_shafts.h):
// the sun's beam scattered once towards an eye under the water.
// The particles' scattering coefficient, 1/m: Petzold 1972's clear ocean
// water (the Bahamas' Tongue of the Ocean, 530 nm), b = 0.037 (Mobley 1994,
// "Light and Water", table 3.10), the clear water Swell's scenes show.
#define SWELL_WATER_SCATTERING_PER_M 0.037
// The Henyey-Greenstein 1941 phase function's asymmetry g (the mean cosine
// of the scattering angle) matching Petzold's average particle phase
// function: g = 0.924 (Mobley, Sundman and Boss 2002, "Phase function
// effects on oceanic light fields", Applied Optics 41(6)). So forward a
// lobe that the shafts show mainly looking towards the sun.
#define SWELL_WATER_PHASE_G 0.924
// Samples along each view ray through the caustics map, and how far they
// reach, m: half the map's side (past it the map holds the mean alone, so
// the shafts' pattern ends there; the mean itself is integrated in closed
// form over the whole path). The samples crowd towards the eye (their
// spacing grows linearly), where shafts are nearest and widest on screen.
#define SWELL_SHAFTS_STEPS 16
#define SWELL_SHAFTS_REACH_M 24.0
// Spray (shaders/spray.vert): none below Beaufort 7, "near gale", whose
// lowest wind is 13.9 m/s at 10 m (WMO Beaufort scale; WMO-No. 8, 2018);
// its amount grows with the wind to full at Beaufort 10's lowest, 24.5 m/s.
#define SWELL_SPRAY_ONSET_WIND_MPS 13.9
#define SWELL_SPRAY_FULL_WIND_MPS 24.5
// The particles: SWELL_SPRAY_SLOTS in each cell of a square lattice of
// SWELL_SPRAY_CELLS^2 cells of SWELL_SPRAY_CELL_M, anchored to the world and
// following the eye (160 m across: farther spray is thinner than a pixel
// and inside the haze of any sea that makes it), each living
// SWELL_SPRAY_LIFETIME_S and born again at once elsewhere.
#define SWELL_SPRAY_CELLS 64
#define SWELL_SPRAY_CELL_M 2.5
#define SWELL_SPRAY_SLOTS 12
#define SWELL_SPRAY_LIFETIME_S 1.6
// A clump's drops (shaders/spray.glsl, sprayTau_s): the first
// SWELL_SPRAY_MIST_DROPS fine mist the wind takes up at once, drawn as
// streaks of their path over the last SWELL_SPRAY_MIST_TRAIL_S (the sheet a
// gale tears off a crest), the rest larger drops that fall back in arcs,
// streaks of SWELL_SPRAY_DROP_TRAIL_S.
#define SWELL_SPRAY_DROPS 5
#define SWELL_SPRAY_MIST_DROPS 3
#define SWELL_SPRAY_MIST_TRAIL_S 0.2
#define SWELL_SPRAY_DROP_TRAIL_S 0.1
// Spray from the bow of a hull under way (shaders/spray.vert built with
// SWELL_BOW_SPRAY 1; objects/bow_spray.h): the first SWELL_BOW_SPRAY_HULLS
// bodies under way, SWELL_BOW_SPRAY_SLOTS slots each (even slots to
// starboard, odd to port), living as the crest spray's clumps do
// (SWELL_SPRAY_LIFETIME_S), born on the bow's waterline from the stem aft
// over SWELL_BOW_SPRAY_REACH of its length, given as SWELL_BOW_SPRAY_STATIONS
// points a side. Whether a life is drawn and how fast its sheet leaves
// follow the hull at its birth: SWELL_BOW_SPRAY_HISTORY samples of it, one
// a water sample of the bodies' steps (SWELL_BOW_SPRAY_SAMPLES_PER_S),
// newest first, longer together than a life. A life's cell key is
// (its body's index, SWELL_BOW_SPRAY_CELL_Y): no lattice cell of the crest
// spray lies there (5000 km from the origin).
#define SWELL_BOW_SPRAY_HULLS 2
#define SWELL_BOW_SPRAY_SLOTS 256
#define SWELL_BOW_SPRAY_STATIONS 5
#define SWELL_BOW_SPRAY_REACH 0.3
#define SWELL_BOW_SPRAY_HISTORY 56
#define SWELL_BOW_SPRAY_SAMPLES_PER_S 30
#define SWELL_BOW_SPRAY_CELL_Y (-2000000)
// Its drops (shaders/spray.glsl, bowSprayTau_s): SWELL_BOW_SPRAY_DROPS a
// clump, the first SWELL_SPRAY_MIST_DROPS mist as the crest's, the rest the
// sheet's drops of 0.4 to 1.0 mm, drawn as streaks of
// SWELL_BOW_SPRAY_SHEET_TRAIL_S.
#define SWELL_BOW_SPRAY_DROPS 8
#define SWELL_BOW_SPRAY_SHEET_TRAIL_S 0.2
// Each clump is also a piece of the water sheet itself (spray.glsl,
// bowSheetTorn): SWELL_BOW_SPRAY_SHEET_MIN_MM to _MAX_MM thick, torn by
// holes SWELL_BOW_SPRAY_HOLE_SPACING_M apart that open at the
// Taylor-Culick speed; drawn as a wide streak of its path over the last
// SWELL_BOW_SPRAY_PIECE_TRAIL_S.
#define SWELL_BOW_SPRAY_SHEET_MIN_MM 0.5
#define SWELL_BOW_SPRAY_SHEET_MAX_MM 2.0
#define SWELL_BOW_SPRAY_HOLE_SPACING_M 0.15
#define SWELL_BOW_SPRAY_PIECE_TRAIL_S 0.15
// Sea water as the sheet tears (Taylor-Culick, bowSheetRetraction_mps) and
// drops fall (Stokes drag, sprayTau_s): surface tension, N/m, and
// density, kg/m^3. A slamming bow's flare is taken no flatter than 20
// degrees (bowSlamJet_mps): its cotangent, where Wagner's jet would grow
// without bound.
#define SWELL_SEA_WATER_SURFACE_TENSION_N_PER_M 0.073
#define SWELL_SEA_WATER_DENSITY_KG_PER_M3 1025.0
#define SWELL_BOW_SPRAY_MAX_FLARE_COT 2.75
// The spray's passes (src/render/spray_passes.cpp): spray_clumps.comp
// evaluates every slot's clump in workgroups of SWELL_SPRAY_GROUP,
// spray_list.comp lists the living ones in one workgroup of
// SWELL_SPRAY_LIST_GROUP, spray_streaks.comp evaluates each living clump's
// streaks (workgroups of SWELL_SPRAY_GROUP, as many as the list says), and
// spray.vert draws them as triangle strips of SWELL_SPRAY_STRIP_VERTICES
// vertices (4 point pairs and the first and last again, joining the strips
// without a gap: one draw of them all). Their shader storage bindings: the
// clumps, the list, the commands of the streaks' dispatch and draw (which
// the list writes), and the streaks.
#define SWELL_SPRAY_GROUP 64
#define SWELL_SPRAY_LIST_GROUP 256
#define SWELL_SPRAY_STRIP_VERTICES 10
#define SWELL_STORAGE_SPRAY_CLUMPS 4
#define SWELL_STORAGE_SPRAY_LIST 5
#define SWELL_STORAGE_SPRAY_COMMANDS 6
#define SWELL_STORAGE_SPRAY_STREAKS 7

// The temporal resolve (shaders/temporal_resolve.frag, render/temporal_resolve.h,
// docs/RENDERING.md "Temporal resolve"): the main pass's depth and the
// accumulated history it reads (the frame's colour: SWELL_UNIT_POST_SOURCE).
#define SWELL_UNIT_TEMPORAL_DEPTH 18
#define SWELL_UNIT_TEMPORAL_HISTORY 19
// The clip box per drawn pixel the resolve reads (its centre and the pixel's
// water mark; its half extent and the pixel's depth), gathered at the drawn
// size by shaders/temporal_neighbourhood.frag.
#define SWELL_UNIT_TEMPORAL_BOX_CENTRE 21
#define SWELL_UNIT_TEMPORAL_BOX_EXTENT 22
// The most weight the history holds, in frames of a sample at the pixel's
// centre: a still view ends up averaging about the last this many frames
// (each new one weighs 1/this), which is what hides the jitter's steps and
// the low resolution's, while a change takes about this many frames to
// settle where the neighbourhood clip below does not catch it.
#define SWELL_TEMPORAL_MAX_WEIGHT 10.0
// ...and on the water while the waves move (the simulated time changed since
// the last frame): its pattern travels with the waves' phase, each
// wavelength at its own speed, which no one motion per pixel follows, so
// the water keeps a short history: each new frame weighs at least two
// thirds, which keeps some of the jitter's smoothing without dragging the
// crests (measured in tests/gl/test_temporal_resolve.cpp: at 3 frames the
// moving water strayed further from a full-quality frame than frames with
// no history did). It converges fully while the time stands.
#define SWELL_TEMPORAL_WATER_MAX_WEIGHT 1.5
// The box the reprojected history is clipped to: the mean of the frame's
// 3x3 neighbourhood (YCoCg) plus or minus this many standard deviations
// (Salvi 2016, "An excursion in temporal supersampling", GDC: variance
// clipping). Smaller rejects more (less ghosting, more flicker).
#define SWELL_TEMPORAL_CLIP_SIGMAS 1.25
// The number of frames in the jitter's cycle (Halton 2, 3: points 1..this).
#define SWELL_TEMPORAL_JITTER_PHASES 16

#endif

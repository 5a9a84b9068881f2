// What tests, the benchmark and tools see of a Renderer beyond what a host
// needs: the frame counters (Renderer::counters()), the water's vertex
// capture, the water shading terms left out, the temporal jitter and the
// island's level-of-detail tolerance. A host needs none of it.
#pragma once

#include "swell/export.h"

#include "swell/camera.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace swell {

// The CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID) that Swell's
// simulation work for a frame took, ms, by part. GL calls made in these parts
// count as far as the driver works on the calling thread (uploads,
// validation, and on a software rasteriser whatever it does there before
// handing work on); what a driver runs on threads of its own (llvmpipe's
// rasteriser and compute threads: the emulated GPU) does not, nor does a
// PassObserver's own time. Not in any part: issuing the passes' draws and
// their state (the pass table of `swell bench` has those).
struct SWELL_API SimulationCpuTime {
    // The wave model: its frame's preparation (WaveModelGpu::prepareFrame:
    // the spectral model's dispatches, and on a software rasteriser the
    // steps of a foam replay before the last) and each view's (prepareView,
    // bind).
    double model_ms = 0.0;
    // The floating bodies and their wake stepped to the frame's time (their
    // own water queries included), the wake's frame blended and uploaded.
    double bodies_ms = 0.0;
    // The frame's queries of the water: answered on the GPU (the dispatch,
    // the wait for it, the triangles found among its vertices) or, for a
    // model whose CPU queries are cheap, with those; the scene objects'
    // poses found with them, and a view's query of which side of the water
    // its eye is when it is not the simulated viewpoint.
    double queries_ms = 0.0;
    // Each view's culling and uniforms: the grid's tiles culled, the frame
    // uniforms and the world's boxes found, the uniforms and the surface
    // sources' parameters uploaded (every pass's).
    double views_ms = 0.0;
    double total_ms() const { return model_ms + bodies_ms + queries_ms + views_ms; }
};

// Swell's GPU work other than drawing, counted where the library makes the
// calls (swell/wave_model_gpu.h's Work): exact, the same in every run and on
// every machine, except a frame that replays the foam's history, whose
// steps before the last run on the CPU on a software rasteriser.
struct SWELL_API GpuWork {
    int dispatches = 0;         // glDispatchCompute calls
    int barriers = 0;           // glMemoryBarrier calls
    int mipmaps = 0;            // glGenerateTextureMipmap calls
    long long bytesWritten = 0; // texels the dispatches, mipmaps, clears and image uploads wrote, times their formats' sizes
};

// What the last advanceTo() did, and what the views drawn since drew (their
// sums), for the benchmark and tests. advanceTo() starts them again.
struct SWELL_API FrameCounters {
    long long waterTriangles = 0;
    long long worldTriangles = 0;
    long long causticsTriangles = 0; // the surface's triangles refracted into the caustics map (each to every slice)
    int drawCalls = 0;         // the views': every glDraw* call Swell made for them
    int views = 0;             // views drawn since the last advanceTo()
    int simulationSteps = 0;   // 1 when the last advanceTo() moved the simulation to a new time or viewpoint
    int floatingBodies = 0;  // rigid bodies in the scene (swell/floating_body.h)
    // Their integration steps taken for this frame (1/120 s each, all
    // bodies), and their wake's (1/30 s each), since the last advanceTo():
    // those anticipate() had taken ahead included.
    long long bodySteps = 0;
    long long wakeSteps = 0;
    double wakeSteps_ms = 0.0; // the wall time the wake's steps took, ms, on whichever thread took them
    // The CPU time the bodies' worker thread spent stepping ahead of this
    // frame (anticipate()) since the last advanceTo(), ms, its own clock:
    // Swell's CPU time, but not the calling thread's, so not in simulationCpu.
    double bodiesAheadCpu_ms = 0.0;
    int oceanTransforms = 0;   // the wave model's sets of inverse FFTs for this frame (spectral model)
    int foamSteps = 0;         // its foam's steps for this frame: more than one is a replay of its history
    // The frame's own queries of the water (each floating object's, the
    // viewpoint's side of it within the waves' reach): those answered on the
    // GPU from what it draws (WaveModelGpu::answersFrameQueries, the
    // spectral model), and those answered with the wave model's CPU queries
    // (every one of a model whose CPU queries are cheap; for the others,
    // a query whose drawn triangle lay beyond the GPU's block of vertices).
    int queriesOnGpu = 0;
    int queriesOnCpu = 0;
    // The boxes the views' culling of the water grid tested against their
    // frusta (blocks, quadtree nodes, tiles; part of views_ms): exact, the
    // same in every run, for a figure of the culling's work that no load
    // moves.
    long long cullBoxesTested = 0;
    // The host's motion vectors (DrawOptions::motionVectors): their draw
    // calls (the water's previous vertices, the grid, Swell's world, the
    // sky) and the triangles drawn again for them; 0 when no view asks for
    // them, and in drawCalls and waterTriangles / worldTriangles never.
    int motionVectorDraws = 0;
    long long motionVectorTriangles = 0;
    // The views' contact passes (docs/RENDERING.md "Foam where water meets
    // what stands in it"): those drawn (their draw calls are in drawCalls,
    // their distance passes in viewsGpu where anything was drawn); 0 where
    // nothing of the world reaches the water near the eye, or the sea is flat.
    // Their triangles of Swell's world (not in worldTriangles, which counts
    // the views' pictures).
    int contactMaps = 0;
    long long contactTriangles = 0;
    // Every draw call of the views (the sky's bake and the anti-aliasing's
    // filter included) is drawCalls above; the rest of the GPU's work:
    GpuWork simulationGpu; // advanceTo()'s: the wave model's for the frame
    GpuWork viewsGpu;      // the views': the wave model's for each (none for Swell's own models), the caustics map's clear and mip chain where drawn, the spray's passes, the water's tile list and clear when drawn in two passes
    SimulationCpuTime simulationCpu;
};

// The calls behind Renderer's own: each takes the renderer it works on.
class SWELL_API RendererTesting {
public:
    // For measuring what each term of the water shading costs (swell bench):
    // a renderer with the terms left out, a bitwise or of SWELL_TERM_*
    // (swell/gpu/variants.h), each replaced by its cheapest stand-in.
    // 0 draws the water in full.
    static std::unique_ptr<Renderer> create(const Scene& scene, RendererOptions options, unsigned omittedWaterTerms);

    // Binds the water program with transform feedback capture of
    // vRestPoint, vPosition and vNormal (8 floats per vertex) for this
    // frame setup, draws all the grid's vertices as points into `buffer`,
    // and returns the vertex count. Render origin: the camera's x,z.
    // drawnIndices, when given, receives the triangles (three vertex indices
    // each) a frame of this size would draw: the tiles in view.
    static int captureWaterVertices(Renderer& renderer, const Camera& camera, double time_s, unsigned buffer,
                                    glm::ivec2 size = {640, 480}, std::vector<std::uint32_t>* drawnIndices = nullptr);
    // The number of vertices captureWaterVertices writes.
    static int waterVertexCount(const Renderer& renderer);

    // Draws every view's frames unjittered (at the pixels' centres), to show
    // what the temporal resolve's jitter brings. Default on.
    static void setTemporalJitter(Renderer& renderer, bool on);

    // Draws the water in one pass, its grid shaded in its own fragments,
    // instead of a visibility pass and one shading run per water pixel
    // (docs/RENDERING.md "The water in two passes"), to compare the two.
    // Default on where the GL lets vertex shaders write storage buffers.
    static void setWaterInTwoPasses(Renderer& renderer, bool on);

    // The largest error, in each pass's own pixels, that the built-in
    // island's level of detail may show (docs/RENDERING.md "The island's
    // levels of detail"); 0 draws its full grid in every pass. Default 0.5.
    // Throws swell::InputError below 0.
    static void setIslandTolerance(Renderer& renderer, double tolerance_px);

    // Leaves the contact foam out (docs/RENDERING.md "Foam where water meets
    // what stands in it"): no contact pass, no foam round what stands in the
    // water, for measuring what it costs and shows. Default on.
    static void setContactFoam(Renderer& renderer, bool on);
};

} // namespace swell

// The spray's tunables that C++ and GLSL share: the crests' spray and the
// bows' (the sea water's physical constants are swell/constants.h's).
// Included by C++ and GLSL alike, so it holds only preprocessor lines and
// comments; every value has its reason above it.
#ifndef SWELL_GPU_SPRAY_H
#define SWELL_GPU_SPRAY_H

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
// A slamming bow's flare is taken no flatter than 20 degrees
// (bowSlamJet_mps): its cotangent, where Wagner's jet would grow without
// bound.
#define SWELL_BOW_SPRAY_MAX_FLARE_COT 2.75
// spray.vert draws the streaks as triangle strips of
// SWELL_SPRAY_STRIP_VERTICES vertices (4 point pairs and the first and last
// again, joining the strips without a gap: one draw of them all).
#define SWELL_SPRAY_STRIP_VERTICES 10

#endif

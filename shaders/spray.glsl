// The spray's kinematics (spray_clumps.comp, spray_streaks.comp): which slot of the
// lattice lives when, where its clump leaves the crest, how its drops fly.
// Every value is a function of the slot, the simulated time and the wind
// alone. The C++ twin is src/render/spray_kinematics.h, line for line;
// tests/gl/test_spray_kinematics.cpp runs both over a set of seeds.
#ifndef SWELL_SPRAY_GLSL
#define SWELL_SPRAY_GLSL

#include "swell/gpu/spray.h"
#include "gpu/constants.glsl"

// A 32-bit integer hash (Wellons 2018, "lowbias32"): every input bit
// changes about half the output bits; GLSL's sin-based hashes are not
// specified to the bit.
uint sprayHash(uint x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// The n-th uniform number in [0, 1) of a key: 24 bits, exact in a float.
float sprayUnit(uint key, uint n) { return float(sprayHash(key + n * 0x9e3779b9u) >> 8u) * (1.0 / 16777216.0); }

// A slot's present life: its key (every random choice of that life), its
// age, and where in its cell it was born (0..1 each way).
struct SprayLife {
    uint key;
    float age_s;
    vec2 inCell;
};

// worldCell: the cell's index in the world; time_s: x the time within a
// period of 4096 lifetimes, y the period's index (float holds the first to
// the microsecond where hours of absolute time would not).
SprayLife sprayLife(ivec2 worldCell, int slot, vec2 time_s)
{
    uint slotKey = sprayHash(uint(worldCell.x) * 0x9e3779b1u ^ sprayHash(uint(worldCell.y) ^ sprayHash(uint(slot))));
    // The slot's lives: each starts at a phase of the slot's own.
    // precise: a driver may fuse a product and a sum into one rounding (an
    // NVIDIA one does); the C++ twin rounds each, and at an hour's time the
    // fused age differs by microseconds, so the age is kept unfused.
    float lifetime_s = float(SWELL_SPRAY_LIFETIME_S);
    precise float local_s = time_s.x + sprayUnit(slotKey, 0u) * lifetime_s;
    float life = floor(local_s / lifetime_s);
    SprayLife l;
    precise float age_s = local_s - life * lifetime_s;
    l.age_s = age_s;
    uint lifeIndex = uint(int(time_s.y)) * 4096u + uint(int(life));
    l.key = sprayHash(slotKey ^ sprayHash(lifeIndex));
    l.inCell = vec2(sprayUnit(l.key, 2u), sprayUnit(l.key, 3u));
    return l;
}

// Whether a life is drawn, from the crest signal: the whitecaps' foam at
// its birth place (exp(-age / lifetime), 1 where a crest folds now), which
// says a crest broke there lately. youngFoam is the foam a second old
// (breakingFoamAmount). Certainly where the foam is under two seconds old
// (youngFoam^2: the spray's life and a little more), never where it is over
// five (youngFoam^5; the crest has run on a wavelength's part), in between
// the likelier the younger; and only a share `amount` (the wind's) of the
// slots. Five rather than four seconds: chosen by eye, the storm's young
// foam is patchy and four left most of its crests bare.
bool sprayLives(uint key, float foam, float youngFoam, float amount)
{
    float young = youngFoam * youngFoam, old = young * young * youngFoam;
    float breaking = clamp((foam - old) / max(young - old, 1e-3), 0.0, 1.0);
    return sprayUnit(key, 1u) < amount && sprayUnit(key, 4u) < breaking;
}

// A drop's launch velocity, m/s: the clump's, up 1 to 4 m/s, downwind 0.3
// to 0.6 of the wind, across it up to 1 m/s either way, and the drop's own
// scatter about it, up to 0.5 m/s each way across and up (chosen by eye).
vec3 sprayLaunch(uint key, uint drop, vec2 windDirection, float windSpeed_mps)
{
    vec2 across = vec2(-windDirection.y, windDirection.x);
    float side = (sprayUnit(key, 8u) - 0.5) * 2.0 + (sprayUnit(key, 20u + drop) - 0.5);
    vec2 level = windDirection * windSpeed_mps * (0.3 + 0.3 * sprayUnit(key, 7u)) + across * side;
    return vec3(level.x, 1.0 + 3.0 * sprayUnit(key, 6u) + (sprayUnit(key, 30u + drop) - 0.5), level.y);
}

// The air a drop meets over the crest, m/s: 0.8 of the wind at 10 m (the
// logarithmic profile a metre or so up at a gale's roughness; Charnock
// 1955), its gusts 0.9 to 1.1 of that along the wind and 1.5 m/s either
// way across, and lifted 0.2 to 1 m/s by the turbulence in the lee of the
// breaking crest: each drop its own eddy, so a clump's mist fans out into
// a sheet of streaks (chosen by eye).
vec3 sprayAir(uint key, uint drop, vec2 windDirection, float windSpeed_mps)
{
    vec2 across = vec2(-windDirection.y, windDirection.x);
    vec2 level = windDirection * (0.8 * windSpeed_mps * (0.9 + 0.2 * sprayUnit(key, 40u + drop))) +
                 across * (sprayUnit(key, 50u + drop) - 0.5) * 3.0;
    return vec3(level.x, 0.2 + 0.8 * sprayUnit(key, 60u + drop), level.y);
}

// A drop's response time under Stokes drag, s: tau = rho_w d^2 / (18 mu_air)
// (Stokes 1851), rho_w = 1025 kg/m^3, mu_air = 1.8e-5 Pa s. Drops
// 0..SWELL_SPRAY_MIST_DROPS-1 are spume mist, 40 to 120 um, taken up by the
// wind within a hundredth of a second; the rest are drops of 150 to 350 um
// that fall back in arcs (Andreas 1998's spume sizes; Stokes' drag
// overstates the fall of the largest, whose Reynolds number passes 10).
float sprayTau_s(uint key, uint drop)
{
    float u = sprayUnit(key, 10u + drop);
    float d_m = drop < uint(SWELL_SPRAY_MIST_DROPS) ? (40.0 + 80.0 * u) * 1e-6 : (150.0 + 200.0 * u) * 1e-6;
    return float(SWELL_SEA_WATER_DENSITY_KG_PER_M3) * d_m * d_m / (18.0 * 1.8e-5);
}

// A drop's place relative to its birth after age_s, m: under Stokes drag it
// relaxes towards the air's velocity plus its terminal fall g tau,
//   x(a) = v_inf a + (v0 - v_inf) tau (1 - exp(-a / tau)),
// closed form, so a drop's place needs no history.
vec3 sprayDropOffset(vec3 launch_mps, vec3 air_mps, float tau_s, float age_s)
{
    vec3 terminal = air_mps + vec3(0.0, -9.81 * tau_s, 0.0);
    return terminal * age_s + (launch_mps - terminal) * tau_s * (1.0 - exp(-age_s / tau_s));
}

// The bow's spray (the spray's passes built with SWELL_BOW_SPRAY): its lives are
// the crest spray's (sprayLife, keyed by the body and the slot); what
// follows is what differs.

// The sample of the hull's history (newest first, one every
// 1 / SWELL_BOW_SPRAY_SAMPLES_PER_S s, the newest lag_s before now) that
// holds the hull at a life's birth, age_s ago: the last sample before it.
int bowSpraySample(float age_s, float lag_s)
{
    return max(int(ceil((age_s - lag_s) * float(SWELL_BOW_SPRAY_SAMPLES_PER_S))), 0);
}

// Whether a life is drawn: a share of the slots, the hull's at its birth
// (objects/bow_spray.h).
bool bowSprayLives(uint key, float share) { return sprayUnit(key, 1u) < share; }

// A sheet drop's fall speed in still air, m/s, for its diameter: Gunn and
// Kinzer 1949 (J. Meteorol. 6, "The terminal velocity of fall for water
// droplets in stagnant air", table 2) measured 2.06 m/s at 0.5 mm and
// 4.03 m/s at 1.0 mm, close to a line through the origin over 0.4 to
// 1.0 mm (within 3%): 4.03 m/s per mm. Stokes' drag (sprayTau_s) would
// have such drops fall 30 m/s and more: their Reynolds numbers are in the
// hundreds.
float bowSprayFallSpeed_mps(float diameter_m) { return 4030.0 * diameter_m; }

// A drop's response time, s: the mist's as the crest's (sprayTau_s), the
// sheet's drops of 0.4 to 1.0 mm with the drag that gives their measured
// fall speed, linearised: tau = fall speed / g.
float bowSprayTau_s(uint key, uint drop)
{
    if (drop < uint(SWELL_SPRAY_MIST_DROPS))
        return sprayTau_s(key, drop);
    float d_m = (400.0 + 600.0 * sprayUnit(key, 10u + drop)) * 1e-6;
    return bowSprayFallSpeed_mps(d_m) / 9.81;
}

// The speed of the jet a bow's flare throws as it plunges into the water
// at plunge_mps (the water's rise less the bow's), m/s. Wagner 1932: a
// wedge whose sides meet the calm water at beta, entering it at V, wets a
// half-width c(t) = (pi / 2) V t cot(beta), so its spray root runs out
// along the water at (pi / 2) V cot(beta), and the jet the root throws
// leaves along the body at twice the root's speed (Faltinsen 2005,
// "Hydrodynamics of High-Speed Marine Vehicles", ch. 8, Wagner's jet;
// Zhao and Faltinsen 1993, J. Fluid Mech. 246, "Water entry of
// two-dimensional bodies"): pi V cot(beta). flareCot: cot(beta) of the
// bow's flare (objects/bow_spray.h's BowLine::flareCot), at most that of
// 20 degrees, where Wagner's flat-plate limit would throw it ever faster.
float bowSlamJet_mps(float plunge_mps, float flareCot)
{
    return SWELL_PI * plunge_mps * clamp(flareCot, 0.0, float(SWELL_BOW_SPRAY_MAX_FLARE_COT));
}

// A piece of the bow's sheet: its launch velocity, m/s, in the earth's
// frame. The water the bow meets rises up it at about the hull's speed U
// through the water (relative to the hull the flow meets the stem at U,
// and its stagnation head U^2 / 2g lifts the bow wave) and leaves the
// flare as a sheet thrown up and outward; a bow plunging into a wave
// throws it as Wagner's jet (bowSlamJet_mps). So a piece leaves at 0.5 to
// 1 U plus the jet's root to tip speed (0.5 to 1 of the jet's), outward,
// its rise 0.45 to 0.9 of that; of the hull's own speed it keeps 0.3 to
// 0.6 forward (the sheet is turned aft along the hull), so the hull
// overtakes it and it falls back beside the bow and astern (the shares
// chosen by eye). forward, outward: unit, horizontal (x, z).
vec3 bowSheetLaunch(uint key, vec2 forward, vec2 outward, float speed_mps, float plunge_mps, float flareCot)
{
    float sheet_mps = speed_mps * (0.5 + 0.5 * sprayUnit(key, 70u)) +
                      bowSlamJet_mps(plunge_mps, flareCot) * (0.5 + 0.5 * sprayUnit(key, 71u));
    float rise = 0.45 + 0.45 * sprayUnit(key, 72u);
    vec2 level = outward * (sheet_mps * sqrt(1.0 - rise * rise)) +
                 forward * (speed_mps * (0.3 + 0.3 * sprayUnit(key, 73u)));
    return vec3(level.x, sheet_mps * rise, level.y);
}

// A bow drop's launch velocity, m/s: its piece's (bowSheetLaunch), each
// drop scattered 0.25 m/s about it, so that a clump's drops fly together
// as the torn piece of the sheet (chosen by eye).
vec3 bowSprayLaunch(uint key, uint drop, vec2 forward, vec2 outward, float speed_mps, float plunge_mps, float flareCot)
{
    vec3 scatter = vec3(sprayUnit(key, 80u + drop), sprayUnit(key, 90u + drop), sprayUnit(key, 100u + drop)) - 0.5;
    return bowSheetLaunch(key, forward, outward, speed_mps, plunge_mps, flareCot) + 0.5 * scatter;
}

// The piece of sheet flies as its largest drops do (1 mm; bowSprayTau_s):
// it is water of their size across, and it tears into them.
float bowSheetTau_s() { return bowSprayFallSpeed_mps(1.0e-3) / 9.81; }

// How fast a hole in a sheet of water thickness_m thick opens, m/s: the
// surface tension of its two faces pulls its rim back against the rim's
// inertia (Taylor 1959, Proc. R. Soc. A 253, "The dynamics of thin sheets
// of fluid III. Disintegration of fluid sheets"; Culick 1960, J. Appl.
// Phys. 31, "Comments on a ruptured soap film"): v = sqrt(2 sigma /
// (rho h)), sea water's sigma and rho from swell/constants.h.
float bowSheetRetraction_mps(float thickness_m)
{
    return sqrt(2.0 * float(SWELL_SEA_WATER_SURFACE_TENSION_N_PER_M)
                / (float(SWELL_SEA_WATER_DENSITY_KG_PER_M3) * thickness_m));
}

// The share of a piece of sheet torn open age_s after it left the bow
// (0..1): holes SWELL_BOW_SPRAY_HOLE_SPACING_M apart (chosen by eye: a
// torn piece's size in photographs of bow spray), each opened to a radius
// r = v age at the Taylor-Culick speed, cover pi r^2 / spacing^2 of it;
// the piece SWELL_BOW_SPRAY_SHEET_MIN_MM to _MAX_MM thick (its key's). A
// 1 mm sheet is torn through in 0.22 s, its rims gone to drops.
float bowSheetTorn(uint key, float age_s)
{
    float thickness_m = mix(float(SWELL_BOW_SPRAY_SHEET_MIN_MM), float(SWELL_BOW_SPRAY_SHEET_MAX_MM),
                            sprayUnit(key, 110u)) * 1e-3;
    float r_m = bowSheetRetraction_mps(thickness_m) * age_s;
    float spacing_m = float(SWELL_BOW_SPRAY_HOLE_SPACING_M);
    return min(SWELL_PI * r_m * r_m / (spacing_m * spacing_m), 1.0);
}

#endif

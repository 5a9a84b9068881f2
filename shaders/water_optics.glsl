// The optics of the water's surface between two media, with no GL state:
// shared by the underwater shading and tests/gl/test_underwater_optics.cpp.
#ifndef SWELL_WATER_OPTICS_GLSL
#define SWELL_WATER_OPTICS_GLSL

// Fresnel reflectance of unpolarised light at a smooth interface, from
// index etaI into etaT, for the cosine of the angle of incidence: the mean
// of the s and p reflectances (Fresnel's equations; Hecht, "Optics", 4th
// ed. 2002, eqs. 4.34 and 4.40). 1 beyond the critical angle, where Snell's
// law etaI sin(i) = etaT sin(t) has no transmitted ray.
float fresnelDielectric(float cosI, float etaI, float etaT)
{
    cosI = clamp(cosI, 0.0, 1.0);
    float sinT = etaI / etaT * sqrt(max(1.0 - cosI * cosI, 0.0));
    if (sinT >= 1.0)
        return 1.0;
    float cosT = sqrt(max(1.0 - sinT * sinT, 0.0));
    float rs = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
    float rp = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
    return 0.5 * (rs * rs + rp * rp);
}
#endif

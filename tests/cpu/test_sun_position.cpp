// The sun placed by the date, the time and the place (swell/scene/sun_position.h,
// Michalsky 1988) against published positions, the world's compass axes,
// and sun.time, sun.latitude_deg and sun.longitude_deg in scene files: read,
// written back, and refused with the key's place when wrong. And the sun by
// its angles, sun.elevation_deg and sun.azimuth_deg: the same keys in scene
// files as in sweeps, the azimuth measured one way everywhere (like a
// heading, from -z towards +x; Michalsky's compass azimuth, north -z and
// east +x, is the same number), and each of the sun's three forms written
// back by saveScene as it was given.
#include "swell/camera.h"
#include "swell/dataset/sweep.h"
#include "swell/error.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_file.h"
#include "swell/scene/sun_position.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// Seconds since 1970-01-01T00:00:00Z of a civil date and time at a UTC offset.
double instant(int y, unsigned mo, unsigned d, int h, int mi, double s, double offset_h)
{
    using namespace std::chrono;
    const double day_s = double(sys_days{year{y} / month{mo} / day{d}}.time_since_epoch().count()) * 86400.0;
    return day_s + h * 3600.0 + mi * 60.0 + s - offset_h * 3600.0;
}

// Michalsky (1988) states an accuracy of 0.01 degree from 1950 to 2050;
// the published positions below are from algorithms a hundred times finer,
// so the difference is the algorithm's error. Measured: 0.0025 deg in
// zenith angle, 0.0033 in azimuth, 0.0022 in declination and 0.0056 in
// right ascension. A sign flipped in the equation of the centre (the
// 1.915 sin g term) moves the sun by about 4 degrees; a wrong sidereal
// time or longitude sign by tens.
constexpr double kTolerance_deg = 0.01;

// Reda & Andreas (2004, Solar Energy 76(5), 577-589; NREL/TP-560-34302,
// Table A4.1 and sec. A.5): 2003-10-17 12:30:30 at UTC-7, latitude
// 39.742476, longitude -105.1786, 820 hPa and 11 degrees C: topocentric
// zenith angle 50.11162 deg, azimuth 194.34024 deg (from north, eastward).
// The site's height (1830 m) shifts the sun by its parallax, 0.002 deg,
// which the tolerance holds.
TEST(SunPosition, MatchesTheNrelSpaWorkedExample)
{
    const swell::SolarPosition p =
        swell::solarPosition(instant(2003, 10, 17, 12, 30, 30.0, -7.0), 39.742476, -105.1786, {820.0, 11.0});
    EXPECT_NEAR(90.0 - p.elevation_deg, 50.11162, kTolerance_deg);
    EXPECT_NEAR(p.azimuth_deg, 194.34024, kTolerance_deg);
}

// Meeus (1998, Astronomical Algorithms, 2nd ed., example 25.a): the sun on
// 1992 October 13.0 TD, apparent declination -7.78507 deg (-7 deg 47' 06")
// and apparent right ascension 13h 13m 31.4s = 198.38083 deg. TD runs ahead
// of UT by 59 s in 1992, which moves the sun by 0.0007 deg.
TEST(SunPosition, MatchesMeeusExample25a)
{
    const swell::SolarPosition p = swell::solarPosition(instant(1992, 10, 13, 0, 0, 0.0, 0.0), 0.0, 0.0);
    EXPECT_NEAR(p.declination_deg, -7.78507, kTolerance_deg);
    EXPECT_NEAR(p.rightAscension_deg, 198.38083, kTolerance_deg);
}

// Refraction lifts the sun most at the horizon: Michalsky's (1988) formula
// gives 0.56 deg there at 1013.25 hPa and 15 degrees C (the Almanac's 34'),
// about 0.017 deg at 45 degrees up.
TEST(SunPosition, RefractionLiftsTheSunMostAtTheHorizon)
{
    for (double hour : {6.0, 9.0, 12.0, 15.0, 17.5}) {
        const swell::SolarPosition p = swell::solarPosition(instant(2021, 6, 21, int(hour), int(60.0 * (hour - int(hour))), 0.0, 0.0), 45.0, 0.0);
        const double lift = p.elevation_deg - p.trueElevation_deg;
        EXPECT_GT(lift, 0.0) << hour;
        EXPECT_LT(lift, 0.6) << hour;
    }
    // The horizon's value.
    swell::SolarPosition p;
    for (int step = 0; step < 24 * 180; ++step) { // 20 s steps: the sun rises 0.08 deg in each
        p = swell::solarPosition(instant(2021, 3, 20, 0, 0, 20.0 * step, 0.0), 0.0, 0.0);
        if (std::abs(p.trueElevation_deg) < 0.2 && p.trueElevation_deg > 0.0)
            break;
    }
    EXPECT_NEAR(p.elevation_deg - p.trueElevation_deg, 0.5, 0.1);
}

// Swell's world as a map: north -z, east +x. In the morning the sun is in
// the east, at noon in the south for a northern sea and in the north for a
// southern one, in the evening in the west.
TEST(SunPosition, AzimuthMapsOntoTheWorldsCompass)
{
    // Greenwich, the March equinox of 2021 (20 March): times in UTC.
    const glm::dvec3 morning = swell::sunDirectionOf(swell::solarPosition(instant(2021, 3, 20, 7, 0, 0.0, 0.0), 51.48, 0.0));
    const glm::dvec3 noon = swell::sunDirectionOf(swell::solarPosition(instant(2021, 3, 20, 12, 7, 0.0, 0.0), 51.48, 0.0));
    const glm::dvec3 evening = swell::sunDirectionOf(swell::solarPosition(instant(2021, 3, 20, 17, 0, 0.0, 0.0), 51.48, 0.0));
    EXPECT_GT(morning.x, 0.9 * glm::length(glm::dvec2(morning.x, morning.z))) << "the morning sun is not in the east (+x)";
    EXPECT_GT(noon.z, 0.99 * glm::length(glm::dvec2(noon.x, noon.z))) << "the noon sun is not in the south (+z)";
    EXPECT_NEAR(noon.y, std::sin((90.0 - 51.48) * 3.14159265358979 / 180.0), 0.01) << "noon elevation 90 - latitude";
    EXPECT_LT(evening.x, -0.9 * glm::length(glm::dvec2(evening.x, evening.z))) << "the evening sun is not in the west (-x)";
    // Sydney at its noon (UTC+10): the sun in the north (-z).
    const glm::dvec3 south = swell::sunDirectionOf(swell::solarPosition(instant(2021, 3, 20, 12, 0, 0.0, 10.0), -33.87, 151.21));
    EXPECT_LT(south.z, -0.99 * glm::length(glm::dvec2(south.x, south.z))) << "the southern noon sun is not in the north (-z)";
    for (const glm::dvec3 d : {morning, noon, evening, south})
        EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
}

// The azimuth is a heading (docs/SCENE.md): the sun at azimuth a and
// elevation e is where a camera with yaw_deg = a and pitch_deg = e looks.
TEST(SunPosition, AzimuthIsACameraHeading)
{
    for (double a : {0.0, 30.0, 90.0, 194.34, 270.0})
        for (double e : {0.5, 20.0, 60.0}) {
            swell::SolarPosition p;
            p.azimuth_deg = a;
            p.elevation_deg = e;
            swell::Camera camera;
            camera.yaw_deg = a;
            camera.pitch_deg = e;
            EXPECT_LT(glm::length(swell::sunDirectionOf(p) - camera.forward()), 1e-12) << a << " " << e;
        }
}

swell::InputError sunError(const std::string& toml)
{
    try {
        swell::parseScene(toml, "sun.toml");
    } catch (const swell::InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << toml;
    return swell::InputError({}, "");
}

// A scene that places the sun gets the direction the algorithm gives, and
// saved, it is written back as the instant in UTC with the place (and no
// sun.direction), which reads back to the same sun.
TEST(SunPosition, SceneFilePlacesTheSunAndWritesItBack)
{
    const swell::Scene scene = swell::parseScene(
        "[sun]\ntime = 2003-10-17T12:30:30-07:00\nlatitude_deg = 39.742476\nlongitude_deg = -105.1786\n", "sun.toml");
    ASSERT_TRUE(scene.sun.place);
    EXPECT_EQ(scene.sun.place->time_s, instant(2003, 10, 17, 19, 30, 30.0, 0.0));
    const glm::dvec3 expected = swell::sunDirectionOf(swell::solarPosition(scene.sun.place->time_s, 39.742476, -105.1786));
    EXPECT_LT(glm::length(scene.sun.direction - expected), 1e-12);
    const std::string saved = swell::saveScene(scene);
    EXPECT_NE(saved.find("time = 2003-10-17T19:30:30Z"), std::string::npos) << saved;
    const std::size_t sun = saved.find("\n[sun]\n");
    ASSERT_NE(sun, std::string::npos) << saved;
    const std::string sunTable = saved.substr(sun, saved.find("\n[", sun + 1) - sun);
    EXPECT_EQ(sunTable.find("direction"), std::string::npos) << sunTable;
    const swell::Scene again = swell::parseScene(saved, "saved.toml");
    ASSERT_TRUE(again.sun.place);
    EXPECT_EQ(again.sun.place->time_s, scene.sun.place->time_s);
    EXPECT_EQ(again.sun.direction, scene.sun.direction);
    // Setting a key through the table moves the sun (the viewer's slider).
    swell::Scene moved = scene;
    swell::findParameter("sun.time")->set(moved, 0, scene.sun.place->time_s + 3.0 * 3600.0);
    EXPECT_LT(moved.sun.direction.y, scene.sun.direction.y - 0.2) << "three hours later the sun is lower";
    EXPECT_EQ(swell::formatDateTime(instant(1969, 12, 31, 23, 59, 59.25, 0.0)), "1969-12-31T23:59:59.250Z");
}

TEST(SunPosition, BadPlacementsAreRefusedWithTheKeysPlace)
{
    struct Case {
        const char* toml;
        int line, column;
        const char* says;
    };
    const Case cases[] = {
        {"[sun]\ntime = 2003-10-17\nlatitude_deg = 10.0\nlongitude_deg = 0.0\n", 2, 8, "sun.time must be a date and time with its UTC offset"},
        {"[sun]\ntime = 2003-10-17T12:30:30\nlatitude_deg = 10.0\nlongitude_deg = 0.0\n", 2, 8, "sun.time has no UTC offset"},
        {"[sun]\ntime = 12:30:30\nlatitude_deg = 10.0\nlongitude_deg = 0.0\n", 2, 8, "not a time"},
        {"[sun]\ntime = 1900-01-01T00:00:00Z\nlatitude_deg = 10.0\nlongitude_deg = 0.0\n", 2, 8,
         "sun.time = 1900-01-01T00:00:00Z is out of range; allowed a date and time with its UTC offset, 1950-01-01T00:00:00Z to 2050-01-01T00:00:00Z"},
        {"[sun]\ntime = 2003-10-17T12:30:30Z\nlatitude_deg = 91.0\nlongitude_deg = 0.0\n", 3, 16, "sun.latitude_deg = 91 is out of range; allowed -90..90 deg"},
        {"[sun]\ntime = 2003-10-17T12:30:30Z\nlatitude_deg = 10.0\nlongitude_deg = 181.0\n", 4, 17, "sun.longitude_deg"},
        {"[sun]\ndirection = [0.0, 1.0, 0.0]\ntime = 2003-10-17T12:30:30Z\nlatitude_deg = 10.0\nlongitude_deg = 0.0\n", 3, 8,
         "sun.time and sun.direction exclude each other"},
        {"[sun]\nlatitude_deg = 10.0\nlongitude_deg = 0.0\n", 2, 16, "sun.time is missing"},
        {"[sun]\ntime = 2003-10-17T12:30:30Z\nlongitude_deg = 0.0\n", 2, 8, "sun.latitude_deg is missing"},
    };
    for (const Case& c : cases) {
        const swell::InputError e = sunError(c.toml);
        EXPECT_EQ(e.place().line, c.line) << c.toml << e.what();
        EXPECT_EQ(e.place().column, c.column) << c.toml << e.what();
        EXPECT_NE(e.message().find(c.says), std::string::npos) << c.toml << e.what();
    }
}

// The [sun] table of a saved scene.
std::string sunTableOf(const std::string& saved)
{
    const std::size_t sun = saved.find("\n[sun]\n");
    if (sun == std::string::npos)
        return {};
    return saved.substr(sun, saved.find("\n[", sun + 1) - sun);
}

glm::dvec3 headingOf(double yaw_deg, double pitch_deg)
{
    swell::Camera camera;
    camera.yaw_deg = yaw_deg;
    camera.pitch_deg = pitch_deg;
    return camera.forward();
}

TEST(SunAngles, SceneFileGivesTheSunByItsAnglesAndWritesThemBack)
{
    const swell::Scene scene = swell::parseScene("[sun]\nelevation_deg = 4.0\nazimuth_deg = -5.7\n", "sun.toml");
    ASSERT_TRUE(scene.sun.angles);
    EXPECT_FALSE(scene.sun.place);
    EXPECT_LT(glm::length(scene.sun.direction - headingOf(-5.7, 4.0)), 1e-12);
    const std::string sun = sunTableOf(swell::saveScene(scene));
    EXPECT_NE(sun.find("elevation_deg = 4"), std::string::npos) << sun;
    EXPECT_NE(sun.find("azimuth_deg = -5.7"), std::string::npos) << sun;
    EXPECT_EQ(sun.find("direction"), std::string::npos) << sun;
    EXPECT_EQ(sun.find("time"), std::string::npos) << sun;
    const swell::Scene again = swell::parseScene(swell::saveScene(scene), "saved.toml");
    ASSERT_TRUE(again.sun.angles);
    EXPECT_EQ(again.sun.angles->azimuth_deg, -5.7);
    EXPECT_EQ(again.sun.direction, scene.sun.direction);
}

// Each form saved is the form given: a direction stays a direction, a date
// and place stay a date and place.
TEST(SunAngles, EachFormOfTheSunIsSavedAsGiven)
{
    const swell::Scene byDirection = swell::parseScene("[sun]\ndirection = [0.0, 1.0, -1.0]\n", "sun.toml");
    const std::string direction = sunTableOf(swell::saveScene(byDirection));
    EXPECT_NE(direction.find("direction = [0.0, 1.0, -1.0]"), std::string::npos) << direction;
    EXPECT_EQ(direction.find("elevation_deg"), std::string::npos) << direction;
    const swell::Scene byPlace = swell::parseScene(
        "[sun]\ntime = 2003-10-17T12:30:30-07:00\nlatitude_deg = 39.742476\nlongitude_deg = -105.1786\n", "sun.toml");
    const std::string place = sunTableOf(swell::saveScene(byPlace));
    EXPECT_NE(place.find("time = "), std::string::npos) << place;
    EXPECT_EQ(place.find("elevation_deg"), std::string::npos) << place;
    EXPECT_EQ(place.find("direction"), std::string::npos) << place;
}

// One azimuth: the solar position's (from north towards east), the scene
// file's and the sweep's put the sun in the same place, and that is where a
// camera with that heading looks.
TEST(SunAngles, SolarPositionSceneFileAndSweepMeasureTheAzimuthAlike)
{
    const swell::Scene placed = swell::parseScene(
        "[sun]\ntime = 2003-10-17T12:30:30-07:00\nlatitude_deg = 39.742476\nlongitude_deg = -105.1786\n", "sun.toml");
    const swell::SolarPosition p = swell::solarPosition(placed.sun.place->time_s, 39.742476, -105.1786);
    ASSERT_NEAR(p.azimuth_deg, 194.34, 0.01); // Reda & Andreas (2004), Table A4.1: south-south-west
    const swell::Scene byAngles = swell::parseScene(
        fmt::format("[sun]\nelevation_deg = {}\nazimuth_deg = {}\n", p.elevation_deg, p.azimuth_deg), "sun.toml");
    EXPECT_LT(glm::length(byAngles.sun.direction - placed.sun.direction), 1e-12);
    EXPECT_LT(glm::length(byAngles.sun.direction - headingOf(p.azimuth_deg, p.elevation_deg)), 1e-12);

    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / "sun_angles";
    fs::create_directories(folder);
    std::ofstream(folder / "sweep.toml") << fmt::format(
        "scene = \"storm\"\ncount = 1\n[vary]\n\"sun.elevation_deg\" = {}\n\"sun.azimuth_deg\" = {}\n", p.elevation_deg,
        p.azimuth_deg);
    const swell::Sweep sweep = swell::loadSweepFile(folder / "sweep.toml");
    swell::checkSweep(sweep, placed);
    const swell::Scene swept = swell::sweepSample(sweep, placed, 0).scene;
    EXPECT_LT(glm::length(swept.sun.direction - byAngles.sun.direction), 1e-9);
    ASSERT_TRUE(swept.sun.angles) << "a sample whose sun angles vary gives its sun by them";
    EXPECT_FALSE(swept.sun.place);
}

// Setting one angle through the table (the viewer's slider, a sweep) on a
// sun given by its direction keeps the other angle where the sun was.
TEST(SunAngles, OneAngleSetKeepsTheOther)
{
    swell::Scene scene = swell::parseScene("[sun]\ndirection = [1.0, 1.0, 0.0]\n", "sun.toml"); // east, 45 up
    const swell::Parameter& elevation = *swell::findParameter("sun.elevation_deg");
    const swell::Parameter& azimuth = *swell::findParameter("sun.azimuth_deg");
    EXPECT_NEAR(std::get<double>(azimuth.get(scene, 0)), 90.0, 1e-12);
    EXPECT_FALSE(swell::isPresent(elevation, scene));
    elevation.set(scene, 0, 10.0);
    EXPECT_TRUE(swell::isPresent(elevation, scene));
    EXPECT_FALSE(swell::isPresent(*swell::findParameter("sun.direction"), scene));
    EXPECT_LT(glm::length(scene.sun.direction - headingOf(90.0, 10.0)), 1e-12);
    // And the direction set again gives the sun by its direction.
    swell::findParameter("sun.direction")->set(scene, 0, glm::dvec3(0.0, 1.0, 1.0));
    EXPECT_FALSE(scene.sun.angles);
}

TEST(SunAngles, BadAnglesAreRefusedWithTheKeysPlace)
{
    struct Case {
        const char* toml;
        int line;
        const char* says;
    };
    const Case cases[] = {
        {"[sun]\nelevation_deg = 20.0\n", 2, "sun.azimuth_deg is missing"},
        {"[sun]\nazimuth_deg = 20.0\n", 2, "sun.elevation_deg is missing"},
        {"[sun]\nelevation_deg = 91.0\nazimuth_deg = 0.0\n", 2, "sun.elevation_deg = 91 is out of range; allowed -90..90 deg"},
        {"[sun]\ndirection = [0.0, 1.0, 0.0]\nelevation_deg = 20.0\nazimuth_deg = 0.0\n", 3,
         "sun.elevation_deg and sun.direction exclude each other"},
        // Two forms: refused at the first key of the one written last.
        {"[sun]\nelevation_deg = 20.0\nazimuth_deg = 0.0\ntime = 2003-10-17T12:30:30Z\nlatitude_deg = 10.0\n"
         "longitude_deg = 0.0\n",
         4, "sun.time and sun.elevation_deg exclude each other"},
        {"[sun]\ntime = 2003-10-17T12:30:30Z\nlatitude_deg = 10.0\nlongitude_deg = 0.0\nazimuth_deg = 0.0\n"
         "elevation_deg = 20.0\n",
         5, "sun.azimuth_deg and sun.time exclude each other"},
        {"[sun]\nelevation = 20.0\n", 2, "did you mean 'sun.elevation_deg'"},
        {"[sun]\nazimuth_rad = 1.0\n", 2, "did you mean 'sun.azimuth_deg', in deg?"},
    };
    for (const Case& c : cases) {
        const swell::InputError e = sunError(c.toml);
        EXPECT_EQ(e.place().line, c.line) << c.toml << e.what();
        EXPECT_NE(e.message().find(c.says), std::string::npos) << c.toml << e.what();
    }
}

} // namespace

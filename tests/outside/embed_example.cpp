// The minimal embedding of Swell (docs/LIBRARY.md shows this same file):
// a headless OpenGL context, the default scene, one frame to a PNG.
#include <swell/camera.h>
#include <swell/gl/context.h>
#include <swell/renderer.h>

#include <cstdio>

int main(int argc, char** argv)
{
    const char* output = argc > 1 ? argv[1] : "embedded.png";
    swell::gl::HeadlessContext context;           // OpenGL 4.5 core through EGL, no display needed
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);               // compiles the embedded shaders, builds the grid
    const double time_s = 3.0;
    const swell::Image image = renderer.renderImage(swell::cameraAt(scene.camera, time_s), time_s, {320, 180});
    swell::writePng(image, output);
    // The height of the water drawn in that frame under a point, m: what
    // to put a floating thing on. (waveModel().heightAt() gives the exact
    // surface, with the waves the grid leaves out.)
    const swell::DrawnSurface drawn = renderer.drawnSurface(swell::cameraAt(scene.camera, time_s), time_s);
    std::printf("%s\nheight at (10, -20): %.3f m\n", output, drawn.at({10.0, -20.0}).value().position_m.y);
    return 0;
}

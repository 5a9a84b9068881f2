// A program that loads OpenGL through something other than libepoxy (here
// the system's own <GL/glcorearb.h> declarations, as glad or GLEW would give)
// can include the renderer's header: it must not pull in <epoxy/gl.h>, which
// stops the compile when another GL header came first. Compiled as part of
// the build; a failure to compile is the test failing.
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <swell/camera.h>
#include <swell/gl/context.h>
#include <swell/renderer.h>

// Uses the renderer's API with the other loader's types, so the file is
// about something.
void drawOcean(swell::Renderer& renderer, const swell::Camera& camera, GLuint framebuffer)
{
    renderer.render(camera, 0.0, {640, 360}, framebuffer);
}

/* A libOSMesa.so.8 that makes contexts but offers no OpenGL function at all,
 * as a driver far too old for Glimmer would. The osmesa backend opens
 * libOSMesa.so.8 with dlopen, so a test puts this one's folder first on
 * LD_LIBRARY_PATH for the glimmer it starts (tests/cli/render_test.cpp:
 * what the user is told then). No real driver is behind it: nothing here
 * draws, and a context is only a non-null pointer. */
#include <stddef.h>

typedef struct osmesa_context* OSMesaContext;
typedef void (*OSMESAproc)(void);

static int the_context;

OSMesaContext OSMesaCreateContextAttribs(const int* attribs, OSMesaContext share) {
    (void)attribs;
    (void)share;
    return (OSMesaContext)&the_context;
}

unsigned char OSMesaMakeCurrent(OSMesaContext context, void* buffer, unsigned type, int width, int height) {
    (void)buffer;
    (void)type;
    (void)width;
    (void)height;
    return context == (OSMesaContext)&the_context;
}

void OSMesaDestroyContext(OSMesaContext context) { (void)context; }

OSMESAproc OSMesaGetProcAddress(const char* name) {
    (void)name;
    return NULL;
}

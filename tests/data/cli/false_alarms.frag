#version 330 compatibility
// main sets the globals before it calls shade(), which reads them: Mesa's
// "used uninitialized" about them is a false alarm; the one about t is true
// (tests/cli/error_cascade_test.cpp).
float gK;
vec3 gColor;
in vec2 vST;
vec3 shade() { return gColor * gK * vST.s; }
void main() {
    gK = 0.5;
    gColor = vec3(1., .5, .2);
    gl_FragColor = vec4(shade(), 1.);
    float t;
    gl_FragColor.r += t;
}

#version 330 compatibility
in vec3 vN;
in vec3 vE;
in vec2 vST;
uniform float uStripes;  // stripes around the objects
in vec4 vColor;
void main() {
    vec3 n = normalize(vN);
    float d = max(dot(n, normalize(vec3(1., 1., 1.))), 0.);
    float stripe = step(.5, fract(vST.s * uStripes)) * .3;
    gl_FragColor = vec4(vColor.rgb * (.2 + .8 * d) + stripe, 1.);
}

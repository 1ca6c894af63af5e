#version 330 compatibility
// Diffuse light with stripes along s, so texture coordinates show on every shape.
in vec3 vN;
in vec2 vST;
in vec3 vT;
uniform vec4 uColor;
uniform float uStripes;
void main() {
    float d = max(dot(normalize(vN), normalize(vec3(0.4, 0.6, 1.0))), 0.);
    float stripe = step(0.5, fract(vST.s * uStripes));
    gl_FragColor = vec4(uColor.rgb * (0.25 + 0.75 * d) * (0.6 + 0.4 * stripe), 1.);
}

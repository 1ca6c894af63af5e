#version 330 compatibility
// The object's colour, lit from the upper left front by its normal.
in vec2 vST;
in vec3 vN;
in vec3 vMC;
void main() {
    vec3 L = normalize(vec3(-1., 1., 1.));
    float d = max(dot(normalize(vN), L), 0.);
    gl_FragColor = vec4(gl_Color.rgb * (0.25 + 0.75 * d), 1.);
}

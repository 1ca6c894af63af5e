#version 330 compatibility
uniform sampler2D Noise2;
in vec2 vST;
void main() {
    gl_FragColor = vec4(texture2D(Noise2, vST).rgb, 1.);
}

#version 330 compatibility
uniform sampler2D uTex;
in vec2 vST;
void main() {
    gl_FragColor = vec4(texture2D(uTex, vST).rgb, 1.);
}

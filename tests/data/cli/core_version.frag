#version 400
uniform float uK;
in vec2 vST;

void main()
{
    gl_FragColor = vec4(uK, vST, 1.);
}

#version 330 compatibility

// The scene plus uAdd times its blur, clamped by the 8-bit screen (handed out).
uniform sampler2D BlurUnit;
uniform sampler2D ImageUnit;
uniform float uAdd;

in vec2 vST;

void main( )
{
    vec3 rgb  = texture( ImageUnit, vST ).rgb;
    vec3 blur = texture( BlurUnit, vST ).rgb;
    gl_FragColor = vec4( rgb + uAdd * blur, 1. );
}

#version 330 compatibility

uniform sampler2D BlurUnit;
uniform sampler2D ImageUnit;
uniform float uAdd;

in vec2 vST;

void main( )
{
    vec3 rgb      = texture( ImageUnit, vST ).rgb;
    vec3 rgbblur = texture( BlurUnit, vST ).rgb;
    gl_FragColor = vec4( rgb + uAdd*rgbblur, 1. );
}

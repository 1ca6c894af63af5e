#version 330 compatibility

// The HDR picture drawn into the scene target, unchanged.
uniform sampler2D HdrUnit;

in vec2 vST;

void main( )
{
    gl_FragColor = vec4( texture( HdrUnit, vST ).rgb, 1. );
}

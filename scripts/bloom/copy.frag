#version 330 compatibility

// A plain copy: one GL_LINEAR lookup at the target texel's centre. Into a target
// 1/n the size of its source it reads the 2x2 source texels around the centre
// of each n x n block (and nothing else of the block when n > 2).
uniform sampler2D ImageUnit;

in vec2 vST;

void main( )
{
    gl_FragColor = vec4( texture( ImageUnit, vST ).rgb, 1. );
}

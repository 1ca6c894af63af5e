#version 330 compatibility

uniform float uLevel;

void main( )
{
    gl_FragColor = vec4( uLevel, 0., 0., 1. );
}

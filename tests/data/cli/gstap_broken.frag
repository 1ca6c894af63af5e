#version 330 compatibility

uniform float uLevel;

// The GSTAP prelude goes in after line 1; the error stays on line 9.

void main( )
{
    gl_FragColor = vec4( uLevel * stillNotDeclared, 0., 0., 1. );
}

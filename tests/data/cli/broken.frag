#version 330 compatibility

// Line 7 uses a variable that was never declared.

void main( )
{
    gl_FragColor = vec4( notDeclared, 0., 0., 1. );
}

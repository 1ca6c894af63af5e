#version 330 compatibility

// The built-in Timer (a sawtooth 0..1 over the script's Timer period) as red.
uniform float Timer;

void main( )
{
    gl_FragColor = vec4( Timer, 0., 0., 1. );
}

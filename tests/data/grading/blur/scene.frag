#version 330 compatibility

// The generated scene every student blurs (handed out): a dark ramp, a white
// disc cut by the right edge and a yellow bar on the bottom edge (a blur that
// wraps instead of clamping lights the left and top edges), a saturated blue
// and a saturated red disc (bright in max(r,g,b), dark in luma), white dots.
in vec2 vST;

float disc( vec2 centre, float radius )
{
    return step( length( vST - centre ), radius );
}

void main( )
{
    vec3 c = vec3( 0.04, 0.04, 0.07 ) + 0.30 * vST.t * vec3( 1., 1., 1. );
    c = mix( c, vec3( 1. ), disc( vec2( 0.97, 0.45 ), 0.09 ) );
    c = mix( c, vec3( 1., 0.85, 0.2 ),
             step( 0.30, vST.s ) * step( vST.s, 0.55 ) * step( vST.t, 0.07 ) );
    c = mix( c, vec3( 0.1, 0.2, 1. ), disc( vec2( 0.28, 0.68 ), 0.10 ) );
    c = mix( c, vec3( 1., 0.15, 0.1 ), disc( vec2( 0.68, 0.78 ), 0.08 ) );
    vec2 cell = fract( vST * 5. ) - 0.5;
    c = mix( c, vec3( 0.95 ), step( length( cell ), 0.04 ) * step( vST.t, 0.5 ) * step( 0.2, vST.s ) );
    gl_FragColor = vec4( c, 1. );
}

#version 330 compatibility

// Values a CPU can compute exactly: gl_FragCoord is a pixel's centre
// (x + 0.5, y + 0.5), and these products and sums of it are exact in float.
uniform float uScale;
in vec2 vST;

void main( )
{
    vec3 exact = vec3( gl_FragCoord.x * uScale - 10., gl_FragCoord.x * gl_FragCoord.y, 1000. + gl_FragCoord.y );
    // Columns 0-9: NaN (the log of a negative number); 10-24: +Inf (e^(100+)
    // is beyond a float); 25 on: the column's centre.
    float odd = gl_FragCoord.x < 10. ? log( -1. - gl_FragCoord.y )
              : gl_FragCoord.x < 25. ? exp( 100. + gl_FragCoord.y )
                                     : gl_FragCoord.x;
    gl_FragColor = vec4( fract( exact ), 1. );
}

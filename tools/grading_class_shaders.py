"""The shaders and scripts of tools/grading-class.py's generated class: the
solution's own texts (tests/data/grading/blur/) and each case's version of
them, correct, subtly wrong, broken, slow or endless. Text only."""
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOLUTION = HERE.parent / "tests" / "data" / "grading" / "blur"


def given(name):
    return (SOLUTION / name).read_text(encoding="utf-8")


def replaced(text, old, new, count=1):
    if text.count(old) < count:
        raise SystemExit(f"grading-class.py: '{old}' is not in the solution's text {count} time(s); update the generator")
    return text.replace(old, new)


# ---------------------------------------------------------------- the shaders
# The files every student was handed: the scene, the quad, the composite.
QUAD, SCENE, ADD = given("quad.vert"), given("scene.frag"), given("add.frag")
BRIGHT, BLUR, GLIB = given("bright.frag"), given("blur.frag"), given("blur.glib")

BLUR_1D = """#version 330 compatibility
// One direction of the Gaussian: along s when uHorizontal is 1, along t when 0.
uniform sampler2D ImageUnit;
uniform int uHalfSize;
uniform int uHorizontal;
in vec2 vST;
void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    vec2 dir = uHorizontal == 1 ? vec2( texel.x, 0. ) : vec2( 0., texel.y );
    float sigma = float( uHalfSize ) / 2.;
    vec3 sum = vec3( 0. );
    float total = 0.;
    for( int i = -uHalfSize; i <= uHalfSize; ++i )
    {
        float w = exp( -float( i * i ) / ( 2. * sigma * sigma ) );
        vec2 st = clamp( vST + float( i ) * dir, texel / 2., 1. - texel / 2. );
        sum += w * texture( ImageUnit, st ).rgb;
        total += w;
    }
    gl_FragColor = vec4( sum / total, 1. );
}
"""

SEPARABLE_GLIB = """##OpenGL GLIB
# Exercise: bloom with a separable blur (horizontal, then vertical).
Ortho -1 1 -1 1
LookAt 0 0 1  0 0 0  0 1 0
Texture2D 5 128 128 RGBA8
Texture2D 6 128 128 RGBA8
Texture2D 7 128 128 RGBA8
Texture2D 8 128 128 RGBA8
Vertex quad.vert
RenderToTexture 5
Fragment scene.frag
Program Scene
QuadXY 0 1
RenderToTexture 6
Fragment bright.frag
Program Bright  ImageUnit 5  uThreshold <0.1 0.5 0.9>
QuadXY 0 1
Fragment BLUR1D
RenderToTexture 7
Program BlurH  ImageUnit 6  uHalfSize <1 3 6>  uHorizontal 1
QuadXY 0 1
RenderToTexture 8
Program BlurV  ImageUnit 7  uHalfSize <1 3 6>  uHorizontal 0
QuadXY 0 1
RenderToTexture
Fragment add.frag
Program Bloom  ImageUnit 5  BlurUnit 8  uAdd <0. 1. 2.>
QuadXY 0 1
"""

WHILE_TEXELFETCH = """#version 330 compatibility
// texelFetch with the texel index clamped, and while loops.
uniform sampler2D ImageUnit;
uniform int uHalfSize;
in vec2 vST;
void main( )
{
    ivec2 size = textureSize( ImageUnit, 0 );
    ivec2 here = ivec2( vST * vec2( size ) );
    float s = float( uHalfSize ) * 0.5;
    vec3 acc = vec3( 0. );
    float norm = 0.;
    int y = -uHalfSize;
    while( y <= uHalfSize )
    {
        int x = -uHalfSize;
        while( x <= uHalfSize )
        {
            ivec2 at = clamp( here + ivec2( x, y ), ivec2( 0 ), size - ivec2( 1 ) );
            float w = exp( -float( x * x + y * y ) / ( 2. * s * s ) );
            acc += w * texelFetch( ImageUnit, at, 0 ).rgb;
            norm += w;
            x++;
        }
        y++;
    }
    gl_FragColor = vec4( acc / norm, 1. );
}
"""

FLOAT_COUNTERS = """#version 330 compatibility
// Float loop counters; the 2-D weight as the product of two 1-D weights.
uniform sampler2D ImageUnit;
uniform int uHalfSize;
in vec2 vST;
float g( float x, float s ) { return exp( -x * x / ( 2. * s * s ) ); }
void main( )
{
    vec2 px = vec2( 1. / 128. );
    px = 1. / vec2( textureSize( ImageUnit, 0 ) );
    float r = float( uHalfSize );
    float s = r / 2.;
    vec4 acc = vec4( 0. );
    for( float y = -r; y <= r + 0.5; y += 1. )
        for( float x = -r; x <= r + 0.5; x += 1. )
        {
            vec2 st = min( max( vST + vec2( x, y ) * px, px * 0.5 ), vec2( 1. ) - px * 0.5 );
            acc += g( x, s ) * g( y, s ) * vec4( texture( ImageUnit, st ).rgb, 1. );
        }
    gl_FragColor = vec4( acc.rgb / acc.a, 1. );
}
"""

# The threshold applied to each tap inside the blur: no bright-pass target.
INLINE_THRESHOLD_FRAG = replaced(replaced(replaced(BLUR,
    "uniform int uHalfSize;", "uniform int uHalfSize;\nuniform float uThreshold;"),
    "sum += weight * texture( ImageUnit, st ).rgb;",
    "vec3 c = texture( ImageUnit, st ).rgb;\n"
    "            if( dot( c, vec3( 0.2126, 0.7152, 0.0722 ) ) > uThreshold )\n"
    "                sum += weight * c;"),
    "A 2-D Gaussian", "The bright pass and a 2-D Gaussian in one")

INLINE_THRESHOLD_GLIB = """##OpenGL GLIB
# bright pass and blur in one shader, one target fewer
Ortho -1 1 -1 1
LookAt 0 0 1  0 0 0  0 1 0
Texture2D 5 128 128 RGBA8
Texture2D 7 128 128 RGBA8
Vertex quad.vert
RenderToTexture 5
Fragment scene.frag
Program Scene
QuadXY 0 1
RenderToTexture 7
Fragment glow.frag
Program Glow  ImageUnit 5  uThreshold <0.1 0.5 0.9>  uHalfSize <1 3 6>
QuadXY 0 1
RenderToTexture
Fragment add.frag
Program Bloom  ImageUnit 5  BlurUnit 7  uAdd <0. 1. 2.>
QuadXY 0 1
"""

# The blur inside the composite: the bright pass blurred as it is added.
BLUR_IN_COMPOSITE_FRAG = """#version 330 compatibility
uniform sampler2D ImageUnit;
uniform sampler2D BrightUnit;
uniform int uHalfSize;
uniform float uAdd;
in vec2 vST;
void main( )
{
    vec2 texel = 1. / vec2( textureSize( BrightUnit, 0 ) );
    float sigma = 0.5 * float( uHalfSize );
    vec3 glow = vec3( 0. );
    float wsum = 0.;
    for( int j = -uHalfSize; j <= uHalfSize; j++ )
        for( int i = -uHalfSize; i <= uHalfSize; i++ )
        {
            float w = exp( -float( i*i + j*j ) / ( 2. * sigma * sigma ) );
            glow += w * texture( BrightUnit, clamp( vST + vec2( i, j ) * texel, 0.5 * texel, 1. - 0.5 * texel ) ).rgb;
            wsum += w;
        }
    gl_FragColor = vec4( texture( ImageUnit, vST ).rgb + uAdd * glow / wsum, 1. );
}
"""

BLUR_IN_COMPOSITE_GLIB = """##OpenGL GLIB
Ortho -1 1 -1 1
LookAt 0 0 1  0 0 0  0 1 0
Texture2D 5 128 128 RGBA8
Texture2D 6 128 128 RGBA8
Vertex quad.vert
RenderToTexture 5
Fragment scene.frag
Program Scene
QuadXY 0 1
RenderToTexture 6
Fragment bright.frag
Program Bright  ImageUnit 5  uThreshold <0.1 0.5 0.9>
QuadXY 0 1
RenderToTexture
Fragment bloom.frag
Program Bloom  ImageUnit 5  BrightUnit 6  uHalfSize <1 3 6>  uAdd <0. 1. 2.>
QuadXY 0 1
"""

STEP_BRIGHT = """#version 330 compatibility
uniform sampler2D ImageUnit;
uniform float uThreshold;
in vec2 vST;
void main( )
{
    vec3 c = textureLod( ImageUnit, vST, 0. ).rgb;
    float y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    gl_FragColor = vec4( c * step( uThreshold, y ), 1. );   // step(): y >= uThreshold
}
"""

ODD_SPACING_GLIB = """##OpenGL GLIB
#   CS 450  --  Project 5: bloom
#   (my comments everywhere, my own spacing)

Ortho   -1 1   -1 1\t\t# the quad fills the view
LookAt\t0 0 1   0 0 0   0 1 0

Texture2D  5   128 128  RGBA8     # scene
Texture2D  6   128 128  RGBA8     # bright
Texture2D  7   128 128  RGBA8     # blurred


Vertex    Quad.vert

# ---- pass 1 ----
RenderToTexture   5
Fragment  Scene.frag
Program   Scene
QuadXY 0   1

# ---- pass 2: keep the bright parts ----
RenderToTexture 6
Fragment Bright.frag
Program Bright    \\
\tImageUnit 5     \\
\tuThreshold < 0.1  0.5  0.9 >
QuadXY 0 1

# ---- pass 3: blur ----
RenderToTexture 7
Fragment Blur.frag
Program Blur     ImageUnit 6   uHalfSize <1 3 6>     # wider = more glow
QuadXY 0 1

# ---- pass 4: add ----
RenderToTexture
Fragment Add.frag
Program Bloom ImageUnit 5 BlurUnit 7 uAdd <0.0 1.0 2.0>
QuadXY 0 1
"""

# The threshold on the brightest channel instead of the luma: the saturated
# blue and red discs glow too.
MAX_BRIGHT = replaced(BRIGHT, "float luma = dot( c, vec3( 0.2126, 0.7152, 0.0722 ) );",
                      "float luma = max( c.r, max( c.g, c.b ) );")
# Taps not clamped: GL_REPEAT wraps the right edge's disc onto the left edge.
WRAP_BLUR = replaced(BLUR, "vec2 st = clamp( vST + vec2( i, j ) * texel, 0.5 * texel, 1. - 0.5 * texel );",
                     "vec2 st = vST + vec2( i, j ) * texel;")
# Off by one: the last row and column of the square left out (lopsided).
LOPSIDED_BLUR = replaced(replaced(BLUR, "i <= uHalfSize", "i < uHalfSize"), "j <= uHalfSize", "j < uHalfSize")
# Off by one: a half-size one smaller than asked (uHalfSize 1 does not blur at all).
SMALL_BLUR = replaced(replaced(replaced(BLUR, "i <= uHalfSize", "i <= uHalfSize - 1"),
                               "j <= uHalfSize", "j <= uHalfSize - 1"),
                      "int i = -uHalfSize", "int i = -uHalfSize + 1").replace(
                      "int j = -uHalfSize", "int j = -uHalfSize + 1")
# Weights not normalised.
UNNORMALISED_BLUR = replaced(BLUR, "sum / weightSum", "sum")
# Painted for the default setting: every slider's value written in.
PAINTED_BRIGHT = replaced(BRIGHT, "luma > uThreshold", "luma > 0.5")
PAINTED_BLUR = replaced(replaced(replaced(BLUR, "-uHalfSize", "-3", 2), "<= uHalfSize", "<= 3", 2),
                        "float( uHalfSize )", "3.")
PAINTED_ADD = replaced(ADD, "rgb + uAdd * blur", "rgb + blur")
# The uniform renamed.
RENAMED_BLUR = BLUR.replace("uHalfSize", "uRadius")
# A syntax error.
SYNTAX_BLUR = replaced(BLUR, "float k = -1. / ( 2. * sigma * sigma );", "float k = -1. / ( 2. * sigma * sigma )")
# An endless loop. llvmpipe ends a fragment's loops after about 65,535
# iterations in all (measured: a 1000 x 1000 nest counts 65,535, and a loop
# after it runs once), so a loop whose counter never moves (`j += 0`) is not
# endless there: it ends with a wrong picture after about 6 s a setting (and
# was graded "look"). This one is hostile on purpose: a `while` that never
# ends, around 320 sin() an iteration, more than a minute a setting on two
# cores even when cut at 65,535 iterations.
_CHURN = "".join(f"    a = sin( a * 1.0001 + {k}.0 );\n" for k in range(40))
ENDLESS_BLUR = replaced(replaced(BLUR,
    "void main( )\n{",
    "float churn( float a )\n{\n" + _CHURN + "    return a;\n}\n\nvoid main( )\n{"),
    "gl_FragColor = vec4( sum / weightSum, 1. );",
    "float a = vST.s;\n"
    "    while( a < 2. )   // sin() never reaches 2\n"
    "        a = churn( churn( churn( churn( churn( churn( churn( churn( a ) ) ) ) ) ) ) );\n"
    "    gl_FragColor = vec4( sum / weightSum + step( 3., a ), 1. );")

# Slow but correct: the bright pass redone for every tap from the scene, and the
# normalisation recomputed for every tap over the whole square, over a window
# of 17 x 17 texels whatever the slider (taps outside weigh 0): about
# 17^2 x (2 uHalfSize + 1)^2 exp() a pixel instead of (2 uHalfSize + 1)^2,
# about ten times a plain submission's time. Its loops stay under 65,535
# iterations a pixel in all (49,130 at uHalfSize 6): llvmpipe stops a
# fragment's loops there (see ENDLESS_BLUR), and a wider window (29 x 29)
# made this correct blur draw a wrong picture at uHalfSize 6.
SLOW_BLUR = """#version 330 compatibility
// Correct, but it redoes everything for every tap.
uniform sampler2D ImageUnit;   // the scene
uniform float uThreshold;
uniform int uHalfSize;
in vec2 vST;
float weightAt( int i, int j )
{
    if( abs( i ) > uHalfSize || abs( j ) > uHalfSize ) return 0.;
    float sigma = 0.5 * float( uHalfSize );
    return exp( -float( i*i + j*j ) / ( 2. * sigma * sigma ) );
}
float normalisedWeight( int i, int j )
{
    float total = 0.;
    for( int b = -uHalfSize; b <= uHalfSize; b++ )
        for( int a = -uHalfSize; a <= uHalfSize; a++ )
            total += weightAt( a, b );
    return weightAt( i, j ) / total;
}
void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    vec3 sum = vec3( 0. );
    for( int j = -8; j <= 8; j++ )       // wide enough for any half-size
        for( int i = -8; i <= 8; i++ )
        {
            float w = normalisedWeight( i, j );
            vec3 c = texture( ImageUnit, clamp( vST + vec2( i, j ) * texel, 0.5 * texel, 1. - 0.5 * texel ) ).rgb;
            float luma = dot( c, vec3( 0.2126, 0.7152, 0.0722 ) );
            sum += w * ( luma > uThreshold ? c : vec3( 0. ) );
        }
    gl_FragColor = vec4( sum, 1. );
}
"""
SLOW_GLIB = INLINE_THRESHOLD_GLIB.replace("glow.frag", "slowblur.frag")

BOM = "\ufeff"

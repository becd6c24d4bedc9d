/*
 * glref.c — the kit's OpenGL reference renderer.
 *
 * Draws a scene with OpenGL 1.x fixed-function calls only (glLightfv, glMaterialfv, glBegin …),
 * off screen with OSMesa (Mesa's off-screen renderer: no display, no GPU), and writes the image
 * as a binary PPM (P6, top row first) to standard output. The kit's CPU rasterizer is compared
 * with this image, so the course's sample program and the kit draw the same pixels.
 *
 * It reads a plain-text command script from the file named as its only argument, or from
 * standard input when there is none (or it is "-"). The Rust crate `cg-glref` writes the
 * script from a kit scene; the script mirrors the GL calls one to one, so it can be read side by
 * side with the course's sample program.
 *
 * Build (the crate does this itself, into target/glref/):
 *     cc -std=c99 -O2 -o glref glref.c -lOSMesa
 * Run:
 *     ./glref scene.txt > scene.ppm
 *
 * Every failure — a bad command, a GL error (glGetError after every command), an OSMesa
 * failure — is reported on standard error as "glref: line N: …" and the exit status is 1.
 * Nothing is written to standard output unless the image is complete.
 *
 * ---------------------------------------------------------------------------------------------
 * The command script: one command per line; words separated by spaces or tabs; blank lines and
 * lines starting with '#' are ignored. Numbers are C floats ("0.5", "1e-3"); non-finite numbers
 * are rejected. Matrices are 16 numbers in column-major order (what glLoadMatrixf expects and
 * glam's Mat4::to_cols_array gives). Colours are R G B; GL gets alpha 1.
 *
 *   size W H                   First command. OSMesa context (RGBA8 colour, 24-bit depth) and a
 *                              W×H buffer; glViewport(0, 0, W, H). Sets the fixed state:
 *                              GL_DEPTH_TEST on (glDepthFunc(GL_LESS)), GL_NORMALIZE on,
 *                              GL_DITHER off, glCullFace(GL_BACK), glFrontFace(GL_CCW).
 *   info                       Prints GL_VENDOR, GL_RENDERER and GL_VERSION on standard error.
 *   clear R G B                glClearColor(R, G, B, 0); glClear(GL_COLOR_BUFFER_BIT |
 *                              GL_DEPTH_BUFFER_BIT).
 *   projection M16             glMatrixMode(GL_PROJECTION); glLoadMatrixf(M).
 *   view M16                   glMatrixMode(GL_MODELVIEW); glLoadMatrixf(M): the view matrix.
 *                              Lights given after it are transformed by it to eye space, as in
 *                              the course's program (light fixed in the world).
 *   lighting on|off            glEnable / glDisable(GL_LIGHTING).
 *   light_model_ambient R G B  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, {R, G, B, 1}).
 *   light_model_local_viewer on|off
 *                              glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE / GL_FALSE).
 *   shade_model flat|smooth    glShadeModel(GL_FLAT / GL_SMOOTH). GL_FLAT colours the whole
 *                              triangle with the lit colour of its last (provoking) vertex.
 *   cull_face on|off           glEnable / glDisable(GL_CULL_FACE).
 *   front_face ccw|cw          glFrontFace(GL_CCW / GL_CW).
 *   light I position X Y Z W   glLightfv(GL_LIGHTi, GL_POSITION, …) under the current modelview
 *                              matrix, and glEnable(GL_LIGHTi). I in 0..7. W = 0: directional.
 *   light I ambient|diffuse|specular R G B
 *   light I spot_direction X Y Z     (under the current modelview matrix, as GL_POSITION)
 *   light I spot_cutoff DEG          (0..90, or 180 for no cone)
 *   light I spot_exponent E          (0..128)
 *   light I attenuation KC KL KQ     (GL_CONSTANT / GL_LINEAR / GL_QUADRATIC_ATTENUATION)
 *   texture ID W H             Defines texture ID (0..4095): the next H lines are
 *                                  texels HEX
 *                              each with W texels as 8 hex digits RRGGBBAA, the bottom row first
 *                              (row 0 is t = 0, as glTexImage2D expects). Uploaded as GL_RGBA8.
 *   push M16                   glPushMatrix(); glMultMatrixf(M): an object's model matrix.
 *   pop                        glPopMatrix().
 *   material ambient|diffuse|specular|emission R G B
 *                              glMaterialfv(GL_FRONT_AND_BACK, …, {R, G, B, 1}).
 *   material shininess S       glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, S) (0..128).
 *   color_material on|off      glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE) and
 *                              glEnable / glDisable(GL_COLOR_MATERIAL): glColor sets ka = kd.
 *   texture_use ID nearest|linear repeat|clamp repeat|clamp modulate|replace
 *                              glBindTexture; GL_TEXTURE_MIN/MAG_FILTER; GL_TEXTURE_WRAP_S/T
 *                              (GL_REPEAT / GL_CLAMP_TO_EDGE); glTexEnvi(GL_TEXTURE_ENV_MODE);
 *                              glEnable(GL_TEXTURE_2D). No mipmaps.
 *   texture_off                glDisable(GL_TEXTURE_2D).
 *   begin                      glBegin(GL_TRIANGLES)
 *   n X Y Z                    glNormal3f      (only between begin and end)
 *   t S T                      glTexCoord2f    (only between begin and end)
 *   c R G B                    glColor3f       (only between begin and end)
 *   v X Y Z                    glVertex3f      (only between begin and end)
 *   end                        glEnd()
 *   finish                     glFinish(); writes the image to standard output; must be last.
 *
 * The output: "P6\n<W> <H>\n255\n" and W·H RGB byte triples, the top row first (OSMesa's
 * buffer has row 0 at the bottom, OSMESA_Y_UP; the rows are flipped on output).
 * ---------------------------------------------------------------------------------------------
 */

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_WORDS 24
#define MAX_TEXTURES 4096

/* The state of the reader and of the context. */
static long line_number = 0;
static OSMesaContext context = NULL;
static unsigned char *buffer = NULL; /* W·H RGBA8 pixels, row 0 at the bottom */
static int width = 0, height = 0;
static int inside_begin = 0;         /* between glBegin and glEnd: no glGetError there */
static GLuint texture_names[MAX_TEXTURES];
static int texture_defined[MAX_TEXTURES];

/* Prints "glref: line N: <message>" on standard error and exits with status 1. */
static void fail(const char *format, ...) {
    va_list args;
    va_start(args, format);
    if (line_number > 0) {
        fprintf(stderr, "glref: line %ld: ", line_number);
    } else {
        fprintf(stderr, "glref: ");
    }
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}

static const char *gl_error_name(GLenum e) {
    switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
    }
}

/* Fails with every pending GL error, naming the command that caused it. */
static void check_gl(const char *command) {
    GLenum e;
    int errors = 0;
    while ((e = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "glref: line %ld: %s: %s (0x%04x)\n", line_number, command,
                gl_error_name(e), (unsigned)e);
        if (++errors > 16) break;
    }
    if (errors > 0) exit(1);
}

/* Reads one line of any length into *line (grown as needed). Returns 0 at end of input. */
static int read_line(FILE *in, char **line, size_t *capacity) {
    size_t length = 0;
    int ch;
    while ((ch = fgetc(in)) != EOF) {
        if (length + 2 > *capacity) {
            size_t grown = *capacity ? 2 * *capacity : 256;
            char *p = realloc(*line, grown);
            if (!p) fail("out of memory reading the script");
            *line = p;
            *capacity = grown;
        }
        if (ch == '\n') break;
        (*line)[length++] = (char)ch;
    }
    if (ch == EOF && length == 0) {
        if (ferror(in)) fail("cannot read the script: %s", strerror(errno));
        return 0;
    }
    if (*line == NULL) { /* an empty last line without a buffer yet */
        *line = malloc(1);
        if (!*line) fail("out of memory reading the script");
        *capacity = 1;
    }
    (*line)[length] = '\0';
    return 1;
}

/* Splits a line into at most MAX_WORDS words (in place). Returns the number of words. */
static int split_words(char *line, char **words) {
    int count = 0;
    char *p = line;
    while (*p) {
        while (*p && isspace((unsigned char)*p)) *p++ = '\0';
        if (!*p) break;
        if (count == MAX_WORDS) fail("too many words on one line (at most %d)", MAX_WORDS);
        words[count++] = p;
        while (*p && !isspace((unsigned char)*p)) p++;
    }
    return count;
}

/* A finite float, or failure naming the word. strtof rounds the decimal to the nearest float
 * once (the Rust side prints the shortest decimal of each f32, so it reads back exactly). */
static GLfloat parse_float(const char *word) {
    char *end;
    float x;
    x = strtof(word, &end);
    if (end == word || *end != '\0') fail("\"%s\" is not a number", word);
    if (!isfinite(x)) fail("\"%s\" is not a finite float", word);
    return (GLfloat)x;
}

/* An integer in [lo, hi], or failure naming the word. */
static long parse_int(const char *word, long lo, long hi) {
    char *end;
    long x;
    errno = 0;
    x = strtol(word, &end, 10);
    if (end == word || *end != '\0' || errno == ERANGE) fail("\"%s\" is not an integer", word);
    if (x < lo || x > hi) fail("%ld is outside %ld..%ld", x, lo, hi);
    return x;
}

/* "on" / "off" as GL_TRUE / GL_FALSE. */
static int parse_switch(const char *word) {
    if (strcmp(word, "on") == 0) return 1;
    if (strcmp(word, "off") == 0) return 0;
    fail("expected on or off, got \"%s\"", word);
    return 0;
}

/* Checks that a command has exactly `expected` words after its name. */
static void expect_args(int count, int expected, const char *usage) {
    if (count - 1 != expected) fail("usage: %s", usage);
}

/* Reads `n` floats from words[first..]. */
static void parse_floats(char **words, int first, int n, GLfloat *out) {
    int i;
    for (i = 0; i < n; i++) out[i] = parse_float(words[first + i]);
}

/* `size W H`: the OSMesa context, its buffer and the fixed state of the kit. */
static void command_size(int count, char **words) {
    GLint max_width = 0, max_height = 0;
    expect_args(count, 2, "size W H");
    if (context) fail("size given twice");
    /* RGBA, 8 bits per channel, 24-bit depth buffer, no stencil, no accumulation buffer. */
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!context) fail("OSMesaCreateContextExt failed (is Mesa's OSMesa installed?)");
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_width);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_height);
    width = (int)parse_int(words[1], 1, max_width > 0 ? max_width : 4096);
    height = (int)parse_int(words[2], 1, max_height > 0 ? max_height : 4096);
    buffer = calloc((size_t)width * (size_t)height, 4);
    if (!buffer) fail("out of memory for a %d×%d image", width, height);
    if (!OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, width, height)) {
        fail("OSMesaMakeCurrent failed for a %d×%d RGBA8 buffer", width, height);
    }
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    /* Normals are transformed by the inverse transpose of the modelview matrix and then
     * normalised (GL_NORMALIZE), so scaled model matrices light correctly. */
    glEnable(GL_NORMALIZE);
    /* No ordered dithering: each pixel is the colour rounded to 8 bits. */
    glDisable(GL_DITHER);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    check_gl("size");
}

/* `light I …`: one parameter of GL_LIGHTi. Positions and spot directions are transformed by the
 * modelview matrix current at this call (GL stores them in eye space). */
static void command_light(int count, char **words) {
    GLenum light;
    GLfloat v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const char *what;
    if (count < 3) fail("usage: light I position|ambient|diffuse|specular|spot_direction|"
                        "spot_cutoff|spot_exponent|attenuation …");
    light = GL_LIGHT0 + (GLenum)parse_int(words[1], 0, 7);
    what = words[2];
    if (strcmp(what, "position") == 0) {
        if (count != 7) fail("usage: light I position X Y Z W");
        parse_floats(words, 3, 4, v);
        glLightfv(light, GL_POSITION, v);
        glEnable(light);
    } else if (strcmp(what, "ambient") == 0 || strcmp(what, "diffuse") == 0 ||
               strcmp(what, "specular") == 0) {
        GLenum pname = what[0] == 'a' ? GL_AMBIENT : what[0] == 'd' ? GL_DIFFUSE : GL_SPECULAR;
        if (count != 6) fail("usage: light I %s R G B", what);
        parse_floats(words, 3, 3, v);
        glLightfv(light, pname, v);
    } else if (strcmp(what, "spot_direction") == 0) {
        if (count != 6) fail("usage: light I spot_direction X Y Z");
        parse_floats(words, 3, 3, v);
        glLightfv(light, GL_SPOT_DIRECTION, v);
    } else if (strcmp(what, "spot_cutoff") == 0) {
        if (count != 4) fail("usage: light I spot_cutoff DEG");
        glLightf(light, GL_SPOT_CUTOFF, parse_float(words[3]));
    } else if (strcmp(what, "spot_exponent") == 0) {
        if (count != 4) fail("usage: light I spot_exponent E");
        glLightf(light, GL_SPOT_EXPONENT, parse_float(words[3]));
    } else if (strcmp(what, "attenuation") == 0) {
        if (count != 6) fail("usage: light I attenuation KC KL KQ");
        parse_floats(words, 3, 3, v);
        glLightf(light, GL_CONSTANT_ATTENUATION, v[0]);
        glLightf(light, GL_LINEAR_ATTENUATION, v[1]);
        glLightf(light, GL_QUADRATIC_ATTENUATION, v[2]);
    } else {
        fail("unknown light parameter \"%s\"", what);
    }
}

/* `material …`: glMaterial for front and back faces. */
static void command_material(int count, char **words) {
    GLfloat v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const char *what;
    GLenum pname;
    if (count < 3) fail("usage: material ambient|diffuse|specular|emission|shininess …");
    what = words[1];
    if (strcmp(what, "shininess") == 0) {
        expect_args(count, 2, "material shininess S");
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, parse_float(words[2]));
        return;
    }
    if (strcmp(what, "ambient") == 0) pname = GL_AMBIENT;
    else if (strcmp(what, "diffuse") == 0) pname = GL_DIFFUSE;
    else if (strcmp(what, "specular") == 0) pname = GL_SPECULAR;
    else if (strcmp(what, "emission") == 0) pname = GL_EMISSION;
    else {
        fail("unknown material parameter \"%s\"", what);
        return;
    }
    if (count != 5) fail("usage: material %s R G B", what);
    parse_floats(words, 2, 3, v);
    glMaterialfv(GL_FRONT_AND_BACK, pname, v);
}

static int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* `texture ID W H` and its H lines of texels: glTexImage2D, the bottom row first. */
static void command_texture(int count, char **words, FILE *in, char **line, size_t *capacity) {
    long id, w, h, row, x;
    unsigned char *texels;
    char *row_words[MAX_WORDS];
    expect_args(count, 3, "texture ID W H");
    id = parse_int(words[1], 0, MAX_TEXTURES - 1);
    w = parse_int(words[2], 1, 16384);
    h = parse_int(words[3], 1, 16384);
    texels = malloc((size_t)w * (size_t)h * 4);
    if (!texels) fail("out of memory for a %ld×%ld texture", w, h);
    for (row = 0; row < h; row++) {
        line_number++;
        if (!read_line(in, line, capacity)) fail("texture %ld: row %ld is missing", id, row);
        if (split_words(*line, row_words) != 2 || strcmp(row_words[0], "texels") != 0) {
            fail("texture %ld: expected \"texels HEX\" for row %ld", id, row);
        }
        if (strlen(row_words[1]) != (size_t)w * 8) {
            fail("texture %ld: row %ld needs %ld hex digits (8 per texel)", id, row, w * 8);
        }
        for (x = 0; x < w * 4; x++) {
            int hi = hex_digit(row_words[1][2 * x]), lo = hex_digit(row_words[1][2 * x + 1]);
            if (hi < 0 || lo < 0) fail("texture %ld: row %ld: not a hex digit", id, row);
            texels[(size_t)row * (size_t)w * 4 + (size_t)x] = (unsigned char)(hi * 16 + lo);
        }
    }
    if (!texture_defined[id]) {
        glGenTextures(1, &texture_names[id]);
        texture_defined[id] = 1;
    }
    glBindTexture(GL_TEXTURE_2D, texture_names[id]);
    /* Row 0 of `texels` is the bottom row: glTexImage2D's first row is t = 0. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, (GLsizei)w, (GLsizei)h, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texels);
    free(texels);
}

/* `texture_use ID filter wrap_s wrap_t env`: binds the texture and sets how it is sampled. */
static void command_texture_use(int count, char **words) {
    long id;
    GLint filter, wrap_s, wrap_t, env;
    expect_args(count, 5, "texture_use ID nearest|linear repeat|clamp repeat|clamp "
                          "modulate|replace");
    id = parse_int(words[1], 0, MAX_TEXTURES - 1);
    if (!texture_defined[id]) fail("texture %ld is not defined", id);
    if (strcmp(words[2], "nearest") == 0) filter = GL_NEAREST;
    else if (strcmp(words[2], "linear") == 0) filter = GL_LINEAR;
    else { fail("unknown filter \"%s\"", words[2]); return; }
    if (strcmp(words[3], "repeat") == 0) wrap_s = GL_REPEAT;
    else if (strcmp(words[3], "clamp") == 0) wrap_s = GL_CLAMP_TO_EDGE;
    else { fail("unknown wrap mode \"%s\"", words[3]); return; }
    if (strcmp(words[4], "repeat") == 0) wrap_t = GL_REPEAT;
    else if (strcmp(words[4], "clamp") == 0) wrap_t = GL_CLAMP_TO_EDGE;
    else { fail("unknown wrap mode \"%s\"", words[4]); return; }
    if (strcmp(words[5], "modulate") == 0) env = GL_MODULATE;
    else if (strcmp(words[5], "replace") == 0) env = GL_REPLACE;
    else { fail("unknown texture environment \"%s\"", words[5]); return; }
    glBindTexture(GL_TEXTURE_2D, texture_names[id]);
    /* No mipmaps: the minification filter must not use them (the default does). */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_s);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap_t);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env);
    glEnable(GL_TEXTURE_2D);
}

/* `finish`: glFinish, then the buffer as a binary PPM, the top row first. */
static void command_finish(void) {
    int y;
    unsigned char *row;
    glFinish();
    check_gl("finish");
    row = malloc((size_t)width * 3);
    if (!row) fail("out of memory writing the image");
    printf("P6\n%d %d\n255\n", width, height);
    /* OSMesa's buffer has row 0 at the bottom (OSMESA_Y_UP = 1): write it from the top. */
    for (y = height - 1; y >= 0; y--) {
        const unsigned char *src = buffer + (size_t)y * (size_t)width * 4;
        int x;
        for (x = 0; x < width; x++) {
            row[3 * x + 0] = src[4 * x + 0];
            row[3 * x + 1] = src[4 * x + 1];
            row[3 * x + 2] = src[4 * x + 2];
        }
        if (fwrite(row, 3, (size_t)width, stdout) != (size_t)width) {
            fail("cannot write the image: %s", strerror(errno));
        }
    }
    free(row);
    if (fflush(stdout) != 0) fail("cannot write the image: %s", strerror(errno));
}

/* Runs one command. Returns 1 after `finish`. */
static int run_command(int count, char **words, FILE *in, char **line, size_t *capacity) {
    const char *name = words[0];
    GLfloat v[16];

    /* Between begin and end only the vertex commands are allowed (and glGetError is not). */
    if (inside_begin) {
        if (strcmp(name, "v") == 0) {
            expect_args(count, 3, "v X Y Z");
            parse_floats(words, 1, 3, v);
            glVertex3f(v[0], v[1], v[2]);
        } else if (strcmp(name, "n") == 0) {
            expect_args(count, 3, "n X Y Z");
            parse_floats(words, 1, 3, v);
            glNormal3f(v[0], v[1], v[2]);
        } else if (strcmp(name, "t") == 0) {
            expect_args(count, 2, "t S T");
            parse_floats(words, 1, 2, v);
            glTexCoord2f(v[0], v[1]);
        } else if (strcmp(name, "c") == 0) {
            expect_args(count, 3, "c R G B");
            parse_floats(words, 1, 3, v);
            glColor3f(v[0], v[1], v[2]);
        } else if (strcmp(name, "end") == 0) {
            expect_args(count, 0, "end");
            glEnd();
            inside_begin = 0;
            check_gl("end");
        } else {
            fail("\"%s\" is not allowed between begin and end", name);
        }
        return 0;
    }

    if (strcmp(name, "size") == 0) {
        command_size(count, words);
        return 0;
    }
    if (!context) fail("the first command must be \"size W H\", got \"%s\"", name);

    if (strcmp(name, "info") == 0) {
        expect_args(count, 0, "info");
        fprintf(stderr, "glref: GL_VENDOR %s; GL_RENDERER %s; GL_VERSION %s\n",
                (const char *)glGetString(GL_VENDOR), (const char *)glGetString(GL_RENDERER),
                (const char *)glGetString(GL_VERSION));
    } else if (strcmp(name, "clear") == 0) {
        expect_args(count, 3, "clear R G B");
        parse_floats(words, 1, 3, v);
        glClearColor(v[0], v[1], v[2], 0.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    } else if (strcmp(name, "projection") == 0) {
        expect_args(count, 16, "projection M0 … M15 (column-major)");
        parse_floats(words, 1, 16, v);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(v);
        glMatrixMode(GL_MODELVIEW);
    } else if (strcmp(name, "view") == 0) {
        expect_args(count, 16, "view M0 … M15 (column-major)");
        parse_floats(words, 1, 16, v);
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixf(v);
    } else if (strcmp(name, "lighting") == 0) {
        expect_args(count, 1, "lighting on|off");
        if (parse_switch(words[1])) glEnable(GL_LIGHTING);
        else glDisable(GL_LIGHTING);
    } else if (strcmp(name, "light_model_ambient") == 0) {
        expect_args(count, 3, "light_model_ambient R G B");
        parse_floats(words, 1, 3, v);
        v[3] = 1.0f;
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v);
    } else if (strcmp(name, "light_model_local_viewer") == 0) {
        expect_args(count, 1, "light_model_local_viewer on|off");
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, parse_switch(words[1]) ? GL_TRUE : GL_FALSE);
    } else if (strcmp(name, "shade_model") == 0) {
        expect_args(count, 1, "shade_model flat|smooth");
        if (strcmp(words[1], "flat") == 0) glShadeModel(GL_FLAT);
        else if (strcmp(words[1], "smooth") == 0) glShadeModel(GL_SMOOTH);
        else fail("unknown shade model \"%s\"", words[1]);
    } else if (strcmp(name, "cull_face") == 0) {
        expect_args(count, 1, "cull_face on|off");
        if (parse_switch(words[1])) glEnable(GL_CULL_FACE);
        else glDisable(GL_CULL_FACE);
    } else if (strcmp(name, "front_face") == 0) {
        expect_args(count, 1, "front_face ccw|cw");
        if (strcmp(words[1], "ccw") == 0) glFrontFace(GL_CCW);
        else if (strcmp(words[1], "cw") == 0) glFrontFace(GL_CW);
        else fail("unknown winding \"%s\"", words[1]);
    } else if (strcmp(name, "light") == 0) {
        command_light(count, words);
    } else if (strcmp(name, "texture") == 0) {
        command_texture(count, words, in, line, capacity);
    } else if (strcmp(name, "push") == 0) {
        expect_args(count, 16, "push M0 … M15 (column-major)");
        parse_floats(words, 1, 16, v);
        glMatrixMode(GL_MODELVIEW);
        glPushMatrix();
        glMultMatrixf(v);
    } else if (strcmp(name, "pop") == 0) {
        expect_args(count, 0, "pop");
        glMatrixMode(GL_MODELVIEW);
        glPopMatrix();
    } else if (strcmp(name, "material") == 0) {
        command_material(count, words);
    } else if (strcmp(name, "color_material") == 0) {
        expect_args(count, 1, "color_material on|off");
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        if (parse_switch(words[1])) glEnable(GL_COLOR_MATERIAL);
        else glDisable(GL_COLOR_MATERIAL);
    } else if (strcmp(name, "texture_use") == 0) {
        command_texture_use(count, words);
    } else if (strcmp(name, "texture_off") == 0) {
        expect_args(count, 0, "texture_off");
        glDisable(GL_TEXTURE_2D);
    } else if (strcmp(name, "begin") == 0) {
        expect_args(count, 0, "begin");
        glBegin(GL_TRIANGLES);
        inside_begin = 1;
        return 0; /* no glGetError between glBegin and glEnd */
    } else if (strcmp(name, "finish") == 0) {
        expect_args(count, 0, "finish");
        command_finish();
        return 1;
    } else if (strcmp(name, "n") == 0 || strcmp(name, "t") == 0 || strcmp(name, "c") == 0 ||
               strcmp(name, "v") == 0 || strcmp(name, "end") == 0) {
        fail("\"%s\" is only allowed between begin and end", name);
    } else {
        fail("unknown command \"%s\"", name);
    }
    check_gl(name);
    return 0;
}

int main(int argc, char **argv) {
    FILE *in = stdin;
    char *line = NULL;
    size_t capacity = 0;
    char *words[MAX_WORDS];
    int finished = 0;

    if (argc > 2) fail("usage: glref [SCRIPT]  (reads standard input without SCRIPT or with -)");
    if (argc == 2 && strcmp(argv[1], "-") != 0) {
        in = fopen(argv[1], "r");
        if (!in) fail("cannot open %s: %s", argv[1], strerror(errno));
    }
    while (!finished && read_line(in, &line, &capacity)) {
        int count;
        line_number++;
        count = split_words(line, words);
        if (count == 0 || words[0][0] == '#') continue;
        finished = run_command(count, words, in, &line, &capacity);
    }
    if (!finished) fail("the script ended without \"finish\"");
    /* Anything after `finish` is ignored; the image is complete. */
    free(line);
    OSMesaDestroyContext(context);
    free(buffer);
    if (in != stdin) fclose(in);
    return 0;
}

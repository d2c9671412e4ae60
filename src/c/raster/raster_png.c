/* SPDX-License-Identifier: MIT */
/*
 * raster_png.c -- PNG output and input through libpng. libpng reports errors by
 * longjmp; every object that must be released after a jump is kept in a struct that
 * is not modified between setjmp and the jump (so no volatile locals are needed).
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* open, fstat, fdopen, ftruncate */
#endif
#include "raster.h"
#include "gks_alloc.h"
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <zlib.h>
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

/* Quiet handlers: errors jump back (libpng's default), warnings are dropped. */
static void png_err(png_structp png, png_const_charp msg)
{
    (void)msg;
    png_longjmp(png, 1);
}

static void png_warn(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

typedef struct png_job {
    FILE *fp;
    png_structp png;
    png_infop info;
    png_bytep *rows;
    unsigned char *pix;
} png_job;

/* Where the rows come from: an 8-bit image, a framebuffer resolved row by row into
 * buf (so no whole 8-bit copy of the frame is made), or the caller's function. */
typedef struct row_source {
    const unsigned char *rgb8;
    const gks_raster_fb *fb;
    unsigned char *buf;
    gks_raster_row_fn row;
    void *user;
} row_source;

static const unsigned char *source_row(const row_source *src, int w, int y)
{
    if (src->row)
        return src->row(src->user, y);
    if (src->rgb8)
        return src->rgb8 + (size_t)y * (size_t)w * 3;
    gks_raster_fb_resolve_row(src->fb, y, src->buf);
    return src->buf;
}

static int write_rows(png_job *job, int w, int h, const row_source *src, int compression)
{
    if (setjmp(png_jmpbuf(job->png)))
        return GKS_RASTER_E_IO;
    png_init_io(job->png, job->fp);
    png_set_IHDR(job->png, job->info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (compression == GKS_RASTER_PNG_FAST) {
        png_set_compression_strategy(job->png, Z_RLE);
        png_set_filter(job->png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    } else {
        png_set_compression_level(job->png, compression);
    }
    png_write_info(job->png, job->info);
    for (int y = 0; y < h; y++)
        png_write_row(job->png, source_row(src, w, y));
    png_write_end(job->png, NULL);
    return GKS_RASTER_OK;
}

/* The output file, truncated: an existing regular file (through a symbolic link too), or
 * a new one (*created = 1). A FIFO or device is refused without blocking (O_NONBLOCK:
 * a FIFO without a reader fails at once). NULL on failure. */
static FILE *open_output(const char *path, int *created)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    *created = fd >= 0;
    if (fd < 0 && errno == EEXIST) /* (O_CREAT: through a dangling link, the user's) */
        fd = open(path, O_WRONLY | O_CREAT | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0)
        return NULL;
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || (!*created && ftruncate(fd, 0) != 0) ||
        fcntl(fd, F_SETFL, 0) != 0) {
        close(fd);
        return NULL;
    }
    FILE *fp = fdopen(fd, "wb");
    if (!fp) {
        close(fd);
        if (*created)
            remove(path);
    }
    return fp;
}

static int write_png(const char *path, int w, int h, const row_source *src, int compression)
{
    png_job job = {0};
    int created = 0;
    job.fp = open_output(path, &created);
    if (!job.fp)
        return GKS_RASTER_E_IO;
    int rc = GKS_RASTER_E_NOMEM;
    job.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_err, png_warn);
    if (job.png)
        job.info = png_create_info_struct(job.png);
    if (job.info)
        rc = write_rows(&job, w, h, src, compression);
    png_destroy_write_struct(job.png ? &job.png : NULL, job.info ? &job.info : NULL);
    if (fclose(job.fp) != 0 && rc == GKS_RASTER_OK)
        rc = GKS_RASTER_E_IO;
    if (rc != GKS_RASTER_OK && created)
        remove(path); /* never what the library did not create (a user's file or link) */
    return rc;
}

static int bad_compression(int c)
{
    return c < GKS_RASTER_PNG_FAST || c > GKS_RASTER_PNG_LEVEL_MAX;
}

int gks_raster_png_write_rgb8(const char *path, int w, int h, const unsigned char *rgb8,
                              int compression)
{
    if (!path || !rgb8 || w < 1 || h < 1 || bad_compression(compression))
        return GKS_RASTER_E_ARG;
    row_source src = { .rgb8 = rgb8 };
    return write_png(path, w, h, &src, compression);
}

int gks_raster_png_write_rows(const char *path, int w, int h, gks_raster_row_fn row,
                              void *user, int compression)
{
    if (!path || !row || w < 1 || h < 1 || bad_compression(compression))
        return GKS_RASTER_E_ARG;
    row_source src = { .row = row, .user = user };
    return write_png(path, w, h, &src, compression);
}

int gks_raster_fb_write_png(const gks_raster_fb *fb, const char *path, int compression)
{
    if (!fb || !path || bad_compression(compression))
        return GKS_RASTER_E_ARG;
    row_source src = { .fb = fb, .buf = gks_alloc_array((size_t)fb->width, 3) };
    if (!src.buf)
        return GKS_RASTER_E_NOMEM;
    int rc = write_png(path, fb->width, fb->height, &src, compression);
    gks_free(src.buf);
    return rc;
}

static int read_rows(png_job *job, int *w, int *h)
{
    if (setjmp(png_jmpbuf(job->png)))
        return GKS_RASTER_E_FORMAT;
    png_init_io(job->png, job->fp);
    png_set_sig_bytes(job->png, 8);
    png_set_user_limits(job->png, 65536, 65536);
    png_read_info(job->png, job->info);
    png_uint_32 pw = png_get_image_width(job->png, job->info);
    png_uint_32 ph = png_get_image_height(job->png, job->info);
    int ct = png_get_color_type(job->png, job->info);
    png_set_strip_16(job->png);
    png_set_packing(job->png);
    if (ct == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(job->png);
    if (ct == PNG_COLOR_TYPE_GRAY || ct == PNG_COLOR_TYPE_GRAY_ALPHA) {
        png_set_expand_gray_1_2_4_to_8(job->png);
        png_set_gray_to_rgb(job->png);
    }
    png_set_strip_alpha(job->png);
    png_set_interlace_handling(job->png);
    png_read_update_info(job->png, job->info);
    if (png_get_rowbytes(job->png, job->info) != (size_t)pw * 3)
        return GKS_RASTER_E_FORMAT;
    job->pix = gks_alloc_array((size_t)pw * (size_t)ph, 3);
    job->rows = gks_alloc_array(ph, sizeof *job->rows);
    if (!job->pix || !job->rows)
        return GKS_RASTER_E_NOMEM;
    for (png_uint_32 y = 0; y < ph; y++)
        job->rows[y] = job->pix + (size_t)y * pw * 3;
    png_read_image(job->png, job->rows);
    png_read_end(job->png, NULL);
    *w = (int)pw;
    *h = (int)ph;
    return GKS_RASTER_OK;
}

int gks_raster_png_read_rgb8(const char *path, int *w, int *h, unsigned char **rgb8)
{
    if (!path || !w || !h || !rgb8)
        return GKS_RASTER_E_ARG;
    *rgb8 = NULL;
    png_job job = {0};
    job.fp = fopen(path, "rb");
    if (!job.fp)
        return GKS_RASTER_E_IO;
    unsigned char sig[8];
    int rc = GKS_RASTER_E_FORMAT;
    if (fread(sig, 1, 8, job.fp) == 8 && png_sig_cmp(sig, 0, 8) == 0) {
        rc = GKS_RASTER_E_NOMEM;
        job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, png_err, png_warn);
        if (job.png)
            job.info = png_create_info_struct(job.png);
        if (job.info)
            rc = read_rows(&job, w, h);
        png_destroy_read_struct(job.png ? &job.png : NULL, job.info ? &job.info : NULL, NULL);
    }
    fclose(job.fp);
    gks_free(job.rows);
    if (rc != GKS_RASTER_OK) {
        gks_free(job.pix);
        return rc;
    }
    *rgb8 = job.pix;
    return GKS_RASTER_OK;
}

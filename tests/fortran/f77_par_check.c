/* SPDX-License-Identifier: MIT */
/*
 * f77_par_check.c -- runs the generated Fortran program that prints NAME=value for every
 * PARAMETER of GKS_PAR and GKSE_PAR and compares each with the C binding's enumerations
 * (standard values for enumerations the C binding does not have yet). Fails on a wrong
 * value, an unknown name, or a table name the include files lack.
 * Usage: f77_par_check PROGRAM
 */
#define _POSIX_C_SOURCE 200809L
#include "gks.h"
#include <stdio.h>
#include <string.h>

typedef struct { const char *name; int value; int seen; } entry;

#define C(n, v) { #n, v, 0 },
static entry table[] = {
    C(GBUNDL, GASF_BUNDLED) C(GINDIV, GASF_INDIV)
    C(GCONDI, GFLAG_COND) C(GALWAY, GFLAG_ALWAYS)
    C(GNCLIP, GIND_NO_CLIP) C(GCLIP, GIND_CLIP)
    C(GMONOC, GAVAIL_MONOCHR) C(GCOLOR, GAVAIL_COLR)
    C(GWC, GCOORD_WC) C(GNDC, GCOORD_NDC)
    C(GASAP, GDEFER_ASAP) C(GBNIG, GDEFER_BNIG) C(GBNIL, GDEFER_BNIL) C(GASTI, GDEFER_ASTI)
    C(GUNDET, 0) C(GDETEC, 1)
    C(GMETRE, GDC_METRES) C(GOTHU, GDC_OTHER)
    C(GNEMPT, GDISP_NOT_EMPTY) C(GEMPTY, GDISP_EMPTY)
    C(GIRG, 0) C(GIMM, 1)
    C(GNECHO, GSWITCH_NO_ECHO) C(GECHO, GSWITCH_ECHO)
    C(GHOLLO, GSTYLE_HOLLOW) C(GSOLID, GSTYLE_SOLID) C(GPATTR, GSTYLE_PAT) C(GHATCH, GSTYLE_HATCH)
    C(GNORML, 0) C(GHILIT, 1)
    C(GNONE, GIN_STATUS_NONE) C(GOK, GIN_STATUS_OK) C(GNPICK, GIN_STATUS_NO_IN)
    C(GNCHOI, GIN_STATUS_NO_IN)
    C(GNCLAS, GIN_NONE) C(GLOCAT, GIN_LOC) C(GSTROK, GIN_STROKE) C(GVALUA, GIN_VAL)
    C(GCHOIC, GIN_CHOICE) C(GPICK, GIN_PICK) C(GSTRIN, GIN_STRING)
    C(GSUPPD, GIRG_SUPPR) C(GALLOW, GIRG_ALLOWED)
    C(GL0A, GLEVEL_0A) C(GL0B, GLEVEL_0B) C(GL0C, GLEVEL_0C) C(GL1A, GLEVEL_1A)
    C(GL1B, GLEVEL_1B) C(GL1C, GLEVEL_1C) C(GL2A, GLEVEL_2A) C(GL2B, GLEVEL_2B)
    C(GL2C, GLEVEL_2C)
    C(GNO, GNEW_NO) C(GYES, GNEW_YES)
    C(GREQU, GOP_REQ) C(GSAMPL, GOP_SAMPLE) C(GEVENT, GOP_EVENT)
    C(GGKCL, GST_GKCL) C(GGKOP, GST_GKOP) C(GWSOP, GST_WSOP) C(GWSAC, GST_WSAC)
    C(GSGOP, GST_SGOP)
    C(GABSNT, 0) C(GPRSNT, 1)
    C(GPOSTP, GFLAG_POSTPONE) C(GPERFO, GFLAG_PERFORM)
    C(GHIGHR, 0) C(GLOWER, 1)
    C(GNMORE, GSIMULT_NO_MORE) C(GMORE, GSIMULT_MORE)
    C(GAHNOR, 0) C(GALEFT, 1) C(GACENT, 2) C(GARITE, 3)
    C(GAVNOR, 0) C(GATOP, 1) C(GACAP, 2) C(GAHALF, 3) C(GABASE, 4) C(GABOTT, 5)
    C(GRIGHT, 0) C(GLEFT, 1) C(GUP, 2) C(GDOWN, 3)
    C(GSTRP, 0) C(GCHARP, 1) C(GSTRKP, 2)
    C(GSET, GINQ_SET) C(GREALI, GINQ_REALIZED)
    C(GNPEND, GUPD_NOT_PEND) C(GPEND, GUPD_PEND)
    C(GVECTR, GCLASS_VEC) C(GRASTR, GCLASS_RASTER) C(GOTHWK, GCLASS_OTHER)
    C(GINVIS, 0) C(GVISI, 1)
    C(GOUTPT, GCAT_OUT) C(GINPUT, GCAT_IN) C(GOUTIN, GCAT_OUTIN) C(GWISS, GCAT_WISS)
    C(GMO, GCAT_MO) C(GMI, GCAT_MI)
    C(GINACT, GWS_INACTIVE) C(GACTIV, GWS_ACTIVE)
    C(GPLATT, 0) C(GPMATT, 1) C(GTXATT, 2) C(GFAATT, 3)
    C(GLSOLI, GLINE_SOLID) C(GLDASH, GLINE_DASH) C(GLDOT, GLINE_DOT) C(GLDASD, GLINE_DASH_DOT)
    C(GPOINT, GMARKER_DOT) C(GPLUS, GMARKER_PLUS) C(GAST, GMARKER_ASTERISK) C(GOMARK, GMARKER_CIRCLE) C(GXMARK, GMARKER_CROSS)
    C(GWSNUL, GWS_TYPE_NULL) C(GWSPNG, GWS_TYPE_PNG) C(GWSPLG, GWS_TYPE_PNG_LARGE)
    C(GWSPNO, GWS_TYPE_PNG_OUTPUT)
    C(GWSPDF, GWS_TYPE_PDF) C(GWSSVG, GWS_TYPE_SVG) C(GWSPS, GWS_TYPE_PS) C(GWSEPS, GWS_TYPE_EPS)
    C(GWSMO, GWS_TYPE_MO) C(GWSMI, GWS_TYPE_MI) C(GWSWIS, GWS_TYPE_WISS) C(GWSX11, GWS_TYPE_X11)
    C(GESSFN, GESC_SET_FILE_NAME)
    C(GESNFN, GESC_NCAR_FILE_NAME)
    C(GESNPS, GESC_NCAR_PAUSE)
    C(GESRCS, GESC_RT_CLIP_SECONDARY) C(GESRSA, GESC_RT_SAMPLES) C(GESRMD, GESC_RT_MAX_DEPTH) C(GESRTH, GESC_RT_THREADS) C(GESRPR, GESC_RT_PROGRESS) C(GESRSP, GESC_RT_SPD) C(GESRST, GESC_RT_STATS) C(GESPAA, GESC_PNG_SUPERSAMPLE) C(GESPZC, GESC_PNG_COMPRESSION) C(GESVRS, GESC_VEC_RESOLUTION) C(GESVLJ, GESC_VEC_LINE_JOIN) C(GESVLC, GESC_VEC_LINE_CAP) C(GESVML, GESC_VEC_MITER_LIMIT) C(GESVLS, GESC_VEC_LINE_SCALE) C(GESVPG, GESC_VEC_PAGE) C(GHNONE, GHLHSR_NONE) C(GHLINE, GHLHSR_HIDDEN_LINE) C(GHZBUF, GHLHSR_ZBUFFER) C(GHPNTR, GHLHSR_PAINTER) C(GHRAYT, GHLHSR_RAYTRACE) C(GRNONE, GREFL_NONE) C(GRAMB, GREFL_AMBIENT) C(GRAMBD, GREFL_AMB_DIFF) C(GRAMDS, GREFL_AMB_DIFF_SPEC) C(GAMB, GLIGHT_AMBIENT) C(GDIRE, GLIGHT_DIRECTIONAL) C(GPOSI, GLIGHT_POSITIONAL) C(GSPOT, GLIGHT_SPOT) C(GMXLSI, GKS_MAX_LIGHT_IND) C(GFNONE, GFACET_NONE) C(GFCOLR, GFACET_COLR) C(GFNORM, GFACET_NORM) C(GFCONO, GFACET_COLR_NORM) C(GVCOOR, GVERT_COORD) C(GVCOLR, GVERT_COORD_COLR) C(GVNORM, GVERT_COORD_NORM) C(GVCONO, GVERT_COORD_COLR_NORM) C(GCINDI, GCOLR_INDIRECT) C(GCRGB, GCOLR_RGB) C(GSHNON, GSHAD_NONE) C(GSHCOL, GSHAD_COLR) C(GSHNOR, GSHAD_NORM) C(GPARL, GPROJ_PARAL) C(GPERS, GPROJ_PERSPECT)
    C(GESMIA, GESC_MI_ALLOW_ESCAPES) C(GESISC, GESC_INPUT_SCRIPT)
    C(GARC, GGDP_ARC) C(GCHORD, GGDP_CHORD) C(GPIE, GGDP_PIE) C(GCIRCL, GGDP_CIRCLE)
    C(GELLIP, GGDP_ELLIPSE)
    C(GOFF, GEDGE_OFF) C(GON, GEDGE_ON)
    /* ISO 8651-1 names the C binding has no enumeration for: the standard's values */
    C(GLMA, -3) C(GLMB, -2) C(GLMC, -1) C(GCURNT, 0) C(GSPEC, 1) C(GPLINE, 0) C(GFILLA, 1)
    C(GPROFF, 0) C(GPRON, 1)
#define GKS_FN(id, sym, name, states, mf) { "E" #sym, GFN_##sym, 0 },
#define GKS_FN_RESERVED(id, sym, name) { "E" #sym, id, 0 },
#include "gks_functions.def"
#undef GKS_FN
#undef GKS_FN_RESERVED
};
#undef C

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s PROGRAM\n", argv[0]);
        return 2;
    }
    FILE *p = popen(argv[1], "r");
    if (!p) {
        perror("popen");
        return 2;
    }
    size_t n = sizeof table / sizeof table[0];
    for (size_t i = 0; i < n; i++) /* Fortran names have at most 6 characters: GSBRFQ */
        if (strcmp(table[i].name, "ESBRFEQ") == 0)
            table[i].name = "ESBRFQ";
    int fails = 0, lines = 0;
    char line[256];
    while (fgets(line, sizeof line, p)) {
        char name[64];
        int value;
        if (sscanf(line, " %63[A-Z0-9_]=%d", name, &value) != 2)
            continue;
        lines++;
        size_t i = 0;
        while (i < n && strcmp(table[i].name, name) != 0)
            i++;
        if (i == n) {
            printf("unknown constant %s=%d\n", name, value);
            fails++;
        } else if (table[i].value != value) {
            printf("%s = %d, C binding says %d\n", name, value, table[i].value);
            fails++;
        } else {
            table[i].seen++;
        }
    }
    if (pclose(p) != 0) {
        printf("program failed\n");
        fails++;
    }
    for (size_t i = 0; i < n; i++)
        if (table[i].seen != 1) {
            printf("%s seen %d times\n", table[i].name, table[i].seen);
            fails++;
        }
    printf("%d constants checked, %d failures\n", lines, fails);
    return fails ? 1 : 0;
}

/* SPDX-License-Identifier: MIT */
/*
 * gks_par.c -- the processes of a run under an MPI launcher (gks_par.h). libgks3d does not
 * link libmpi: when the launcher's environment says this process is one of several, the MPI
 * module libgks3d-mpi.so (gks_mpi_module.h) is loaded with dlopen and does the MPI calls;
 * otherwise nothing of MPI is loaded. The state is per process by nature (MPI is
 * initialised once per process), so it lives in this file alone.
 */
#define _GNU_SOURCE 1 /* dladdr */
#include "gks_par.h"
#include "gks_alloc.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GKS3D_MODULE_DIR
#define GKS3D_MODULE_DIR "/usr/local/lib/gks3d" /* CMake passes <libdir>/gks3d */
#endif

int gks_par_frames_default(void)
{
    const char *v = getenv("GKS3D_MPI_FRAMES");
    return v && strcmp(v, "1") == 0;
}

char *gks_par_rank_path(const char *name)
{
    int r = gks_par_rank();
    if (r == 0)
        return gks_strdup(name);
    size_t n = strlen(name) + 16;
    char *p = gks_alloc_array(n, 1);
    if (p)
        snprintf(p, n, "%s.%d", name, r);
    return p;
}

/* The first of the launchers' environment variables that is set, as a non-negative
 * number; -1 if none is set or the value is bad. OpenMPI, MPICH/Hydra and Slurm's PMI,
 * MVAPICH. */
static int env_int(const char *const names[])
{
    for (int i = 0; names[i]; i++) {
        const char *v = getenv(names[i]);
        if (!v || !*v)
            continue;
        char *end;
        long n = strtol(v, &end, 10);
        return *end || n < 0 || n > 1 << 24 ? -1 : (int)n;
    }
    return -1;
}
static int env_size(void)
{
    static const char *const n[] = { "OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MV2_COMM_WORLD_SIZE", NULL };
    int s = env_int(n);
    return s > 1 ? s : 1;
}
static int env_rank(void)
{
    static const char *const n[] = { "OMPI_COMM_WORLD_RANK", "PMI_RANK", "MV2_COMM_WORLD_RANK", NULL };
    int r = env_int(n);
    return r > 0 && r < env_size() ? r : 0;
}

static struct {
    int tried;                  /* the module was looked for */
    const gks_mpi_module *mod;  /* loaded, or NULL */
} par;

/* dlopen of path; on failure the reason goes into why (the first failure is kept). */
static void *try_open(const char *path, char *why, size_t n)
{
    /* RTLD_GLOBAL: OpenMPI's own plugins need libmpi's names in the global scope. */
    void *h = dlopen(path, RTLD_NOW | RTLD_GLOBAL);
    if (!h && !*why) {
        const char *e = dlerror();
        snprintf(why, n, "%s", e ? e : path);
    }
    return h;
}

/* Where the module is: $GKS3D_MPI_MODULE (a file; the build tree's tests), else the folder
 * gks3d/ beside the libgks3d.so that holds this code (found with dladdr, so an installed
 * tree can be moved), else GKS3D_MODULE_DIR (a program linked with libgks3d.a). */
static const gks_mpi_module *load_module(char *why, size_t n)
{
    void *h = NULL;
    const char *env = getenv("GKS3D_MPI_MODULE");
    if (env && *env) {
        h = try_open(env, why, n);
    } else {
        Dl_info info;
        if (dladdr((void *)&gks_par_start, &info) && info.dli_fname) {
            const char *slash = strrchr(info.dli_fname, '/');
            size_t dir = slash ? (size_t)(slash - info.dli_fname) : 0;
            size_t len = dir + sizeof "/gks3d/" GKS_MPI_MODULE_NAME;
            char *p = slash ? gks_alloc_array(len, 1) : NULL;
            if (p) {
                snprintf(p, len, "%.*s/gks3d/%s", (int)dir, info.dli_fname, GKS_MPI_MODULE_NAME);
                FILE *f = fopen(p, "rb");
                if (f) { /* it is there: its failure to load is the reason to give */
                    fclose(f);
                    h = try_open(p, why, n);
                } else {
                    snprintf(why, n, "%s is not installed", p);
                }
                gks_free(p);
            }
        }
        if (!h)
            h = try_open(GKS3D_MODULE_DIR "/" GKS_MPI_MODULE_NAME, why, n);
    }
    if (!h)
        return NULL;
    gks_mpi_module_entry entry;
    void *sym = dlsym(h, GKS_MPI_MODULE_ENTRY);
    memcpy(&entry, &sym, sizeof entry); /* object pointer to function pointer (POSIX) */
    const gks_mpi_module *m = sym ? entry() : NULL;
    if (!m || m->abi != GKS_MPI_MODULE_ABI) {
        snprintf(why, n, "%s is of another release (interface %d, this library's %d)",
                 GKS_MPI_MODULE_NAME, m ? m->abi : -1, GKS_MPI_MODULE_ABI);
        return NULL; /* the handle stays open: the module may have run constructors */
    }
    *why = '\0';
    return m;
}

const gks_mpi_module *gks_par_module(void)
{
    if (!par.tried) {
        par.tried = 1;
        if (env_size() < 2)
            return NULL; /* not launched as one of several processes: no MPI at all */
        char why[512] = "";
        par.mod = load_module(why, sizeof why);
        if (!par.mod && env_rank() == 0)
            fprintf(stderr, "gks3d: started by an MPI launcher as 1 of %d processes, but the MPI "
                    "module cannot be loaded (%s): rank 0 draws the pictures alone\n",
                    env_size(), why);
    }
    return par.mod;
}

int gks_par_rank(void)
{
    int r = par.mod ? par.mod->rank() : -1;
    return r >= 0 ? r : env_rank();
}

int gks_par_size(void)
{
    int n = par.mod ? par.mod->size() : -1;
    return n >= 1 ? n : env_size();
}

int gks_par_start(int *serialized)
{
    const gks_mpi_module *m = gks_par_module();
    if (m)
        return m->start(serialized);
    if (serialized)
        *serialized = 0;
    return 0;
}

void gks_par_lost(void)
{
    if (par.mod)
        par.mod->lost();
}

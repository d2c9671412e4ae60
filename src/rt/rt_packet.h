/* SPDX-License-Identifier: MIT */
/*
 * rt_packet.h -- the coherent path of the tracer (rt_packet.c): packets of up to RT_PACKET
 * rays traced together through the top-level grid by slices (coherent grid traversal, Wald
 * et al. 2006), with the single-ray walk (rt_trace.c) as the fallback. Private to src/rt.
 */
#ifndef GKS3D_RT_PACKET_H
#define GKS3D_RT_PACKET_H

#include "rt_internal.h"

/* The hit record of internal primitive i at t on ray r, as rt_intersect writes it
   (rt_trace.c): the one place that makes an rt_hit. */
void rt_fill_hit(const rt_scene *sc, const rt_rayx *r, long i, double t, rt_hit *h);

/* Packet statistics of one call (tests and benchmarks): packets traced as packets, packets
   handed to the single-ray walk, and rays of traced packets re-traced singly (their hits
   could depend on the order of the tests: rt_packet.c). */
typedef struct rt_packet_stats {
    uint64_t packets, fallback_packets, fallback_rays;
    uint64_t beside; /* nearest-hit packets found beside the grid box without a set-up (of
                        packets: rt_pk_beside, with the AVX2 and AVX-512 kernels) */
} rt_packet_stats;

/* The nearest hits of rays[0..n-1] (n <= RT_PACKET), bit for bit those of
   rt_trace_nearest, into i[] (internal primitive index or -1) and t[], and in rx[] the rays
   as rt_rayx_setup makes them (where i[k] >= 0); ctx: a batch context (its small mailbox).
   Returns 1 if traced as a packet, 0 if the packet was not coherent: then the caller traces
   the rays singly (i, t, rx unspecified). */
int rt_packet_nearest(const rt_scene *sc, rt_ctx *ctx, size_t n, const rt_ray *rays, long *i,
                      double *t, rt_rayx *rx, rt_packet_stats *ps);
/* The same for any-hit rays: occ[k] = 1 if ray k hits a primitive in its range (the answer
   of rt_trace_transmit with any_hit = 1). */
int rt_packet_occluded(const rt_scene *sc, rt_ctx *ctx, size_t n, const rt_ray *rays,
                       unsigned char *occ, rt_packet_stats *ps);

/* rt_intersect_packet / rt_occluded_packet with their packet statistics added to *ps
   (NULL: none) */
int rt_intersect_packet_stats(const rt_scene *sc, size_t n, const rt_ray *rays, rt_hit *hits,
                              rt_packet_stats *ps);
int rt_occluded_packet_stats(const rt_scene *sc, size_t n, const rt_ray *rays,
                             unsigned char *occluded, rt_packet_stats *ps);

/* packets traced as packets (not handed to the single-ray walk) since the process started,
   by every thread (tests: the renderer's eye rays took the coherent path) */
unsigned long long rt_packet_count(void);

/* rays whose rt_rayx the packet path wrote itself and found different from rt_rayx_setup's,
   since the process started (builds without NDEBUG check every one; tests require 0; 0 in
   builds with NDEBUG, which do not check) */
unsigned long long rt_packet_make_differ(void);

/* the name of the kernel that culls rays of a packet ("avx2", "sse", "scalar") */
const char *rt_packet_kernel_name(void);

#endif

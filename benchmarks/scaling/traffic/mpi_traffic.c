/*
 * What each MPI rank sends, counted by interposition (LD_PRELOAD): the
 * point-to-point messages (MPI_Send, Isend, Ssend, Issend, Rsend, Bsend,
 * Sendrecv, and the Fortran mpi_send_, mpi_isend_, mpi_ssend_ that MUMPS
 * calls) with their bytes, and the collective calls (Allreduce, Reduce,
 * Bcast, Allgather(v), Gather(v), Scatter(v), Alltoall(v), Reduce_scatter,
 * Barrier; C and Fortran) with the bytes this rank puts in (its send
 * buffer; for Bcast and Scatter(v) the root's). At MPI_Finalize each rank
 * appends one line to the file named by MPI_TRAFFIC_OUTPUT:
 *   rank <r> p2p_messages <n> p2p_bytes <b> collectives <n> collective_bytes <b>
 * Build: mpicc -shared -fPIC -O2 -o libmpi_traffic.so mpi_traffic.c -ldl
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static long long p2p_messages, p2p_bytes, collectives, collective_bytes;

static long long
bytes_of(int count, MPI_Datatype type)
{
  int size = 0;
  PMPI_Type_size(type, &size);
  return (long long)count * size;
}

static void
p2p(int count, MPI_Datatype type)
{
  ++p2p_messages;
  p2p_bytes += bytes_of(count, type);
}

static void
collective(long long bytes)
{
  ++collectives;
  collective_bytes += bytes;
}

static int
rank_of(MPI_Comm comm)
{
  int r = 0;
  PMPI_Comm_rank(comm, &r);
  return r;
}

static int
size_of(MPI_Comm comm)
{
  int s = 1;
  PMPI_Comm_size(comm, &s);
  return s;
}

/* ---- C point to point ---- */
int
MPI_Send(const void *b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
  p2p(c, t);
  return PMPI_Send(b, c, t, d, g, m);
}
int
MPI_Isend(const void *b, int c, MPI_Datatype t, int d, int g, MPI_Comm m,
          MPI_Request *r)
{
  p2p(c, t);
  return PMPI_Isend(b, c, t, d, g, m, r);
}
int
MPI_Ssend(const void *b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
  p2p(c, t);
  return PMPI_Ssend(b, c, t, d, g, m);
}
int
MPI_Issend(const void *b, int c, MPI_Datatype t, int d, int g, MPI_Comm m,
           MPI_Request *r)
{
  p2p(c, t);
  return PMPI_Issend(b, c, t, d, g, m, r);
}
int
MPI_Rsend(const void *b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
  p2p(c, t);
  return PMPI_Rsend(b, c, t, d, g, m);
}
int
MPI_Bsend(const void *b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
  p2p(c, t);
  return PMPI_Bsend(b, c, t, d, g, m);
}
int
MPI_Sendrecv(const void *sb, int sc, MPI_Datatype st, int d, int sg, void *rb,
             int rc, MPI_Datatype rt, int s, int rg, MPI_Comm m,
             MPI_Status *status)
{
  p2p(sc, st);
  return PMPI_Sendrecv(sb, sc, st, d, sg, rb, rc, rt, s, rg, m, status);
}

/* ---- C collectives ---- */
int
MPI_Barrier(MPI_Comm m)
{
  collective(0);
  return PMPI_Barrier(m);
}
int
MPI_Bcast(void *b, int c, MPI_Datatype t, int root, MPI_Comm m)
{
  collective(rank_of(m) == root ? bytes_of(c, t) : 0);
  return PMPI_Bcast(b, c, t, root, m);
}
int
MPI_Allreduce(const void *sb, void *rb, int c, MPI_Datatype t, MPI_Op o,
              MPI_Comm m)
{
  collective(bytes_of(c, t));
  return PMPI_Allreduce(sb, rb, c, t, o, m);
}
int
MPI_Reduce(const void *sb, void *rb, int c, MPI_Datatype t, MPI_Op o,
           int root, MPI_Comm m)
{
  collective(bytes_of(c, t));
  return PMPI_Reduce(sb, rb, c, t, o, root, m);
}
int
MPI_Allgather(const void *sb, int sc, MPI_Datatype st, void *rb, int rc,
              MPI_Datatype rt, MPI_Comm m)
{
  collective(bytes_of(sc, st));
  return PMPI_Allgather(sb, sc, st, rb, rc, rt, m);
}
int
MPI_Allgatherv(const void *sb, int sc, MPI_Datatype st, void *rb,
               const int *rc, const int *displ, MPI_Datatype rt, MPI_Comm m)
{
  collective(bytes_of(sc, st));
  return PMPI_Allgatherv(sb, sc, st, rb, rc, displ, rt, m);
}
int
MPI_Gather(const void *sb, int sc, MPI_Datatype st, void *rb, int rc,
           MPI_Datatype rt, int root, MPI_Comm m)
{
  collective(bytes_of(sc, st));
  return PMPI_Gather(sb, sc, st, rb, rc, rt, root, m);
}
int
MPI_Gatherv(const void *sb, int sc, MPI_Datatype st, void *rb, const int *rc,
            const int *displ, MPI_Datatype rt, int root, MPI_Comm m)
{
  collective(bytes_of(sc, st));
  return PMPI_Gatherv(sb, sc, st, rb, rc, displ, rt, root, m);
}
int
MPI_Scatter(const void *sb, int sc, MPI_Datatype st, void *rb, int rc,
            MPI_Datatype rt, int root, MPI_Comm m)
{
  collective(rank_of(m) == root ? bytes_of(sc, st) * size_of(m) : 0);
  return PMPI_Scatter(sb, sc, st, rb, rc, rt, root, m);
}
int
MPI_Scatterv(const void *sb, const int *sc, const int *displ, MPI_Datatype st,
             void *rb, int rc, MPI_Datatype rt, int root, MPI_Comm m)
{
  long long bytes = 0;
  if (rank_of(m) == root)
    for (int p = 0; p < size_of(m); ++p)
      bytes += bytes_of(sc[p], st);
  collective(bytes);
  return PMPI_Scatterv(sb, sc, displ, st, rb, rc, rt, root, m);
}
int
MPI_Alltoall(const void *sb, int sc, MPI_Datatype st, void *rb, int rc,
             MPI_Datatype rt, MPI_Comm m)
{
  collective(bytes_of(sc, st) * size_of(m));
  return PMPI_Alltoall(sb, sc, st, rb, rc, rt, m);
}
int
MPI_Alltoallv(const void *sb, const int *sc, const int *sd, MPI_Datatype st,
              void *rb, const int *rc, const int *rd, MPI_Datatype rt,
              MPI_Comm m)
{
  long long bytes = 0;
  for (int p = 0; p < size_of(m); ++p)
    bytes += bytes_of(sc[p], st);
  collective(bytes);
  return PMPI_Alltoallv(sb, sc, sd, st, rb, rc, rd, rt, m);
}
int
MPI_Reduce_scatter(const void *sb, void *rb, const int *rc, MPI_Datatype t,
                   MPI_Op o, MPI_Comm m)
{
  long long bytes = 0;
  for (int p = 0; p < size_of(m); ++p)
    bytes += bytes_of(rc[p], t);
  collective(bytes);
  return PMPI_Reduce_scatter(sb, rb, rc, t, o, m);
}

/* ---- Fortran (MUMPS, ScaLAPACK): count, then call the library's own ---- */
typedef void (*fortran_send)(void *, MPI_Fint *, MPI_Fint *, MPI_Fint *,
                             MPI_Fint *, MPI_Fint *, MPI_Fint *);
typedef void (*fortran_isend)(void *, MPI_Fint *, MPI_Fint *, MPI_Fint *,
                              MPI_Fint *, MPI_Fint *, MPI_Fint *, MPI_Fint *);

static void *
next(const char *name)
{
  void *f = dlsym(RTLD_NEXT, name);
  if (!f)
    {
      fprintf(stderr, "mpi_traffic: no %s\n", name);
      abort();
    }
  return f;
}

static long long
fortran_bytes(MPI_Fint *count, MPI_Fint *type)
{
  return bytes_of(*count, MPI_Type_f2c(*type));
}

void
mpi_send_(void *b, MPI_Fint *c, MPI_Fint *t, MPI_Fint *d, MPI_Fint *g,
          MPI_Fint *m, MPI_Fint *e)
{
  static fortran_send f;
  if (!f)
    f = (fortran_send)next("mpi_send_");
  ++p2p_messages;
  p2p_bytes += fortran_bytes(c, t);
  f(b, c, t, d, g, m, e);
}
void
mpi_ssend_(void *b, MPI_Fint *c, MPI_Fint *t, MPI_Fint *d, MPI_Fint *g,
           MPI_Fint *m, MPI_Fint *e)
{
  static fortran_send f;
  if (!f)
    f = (fortran_send)next("mpi_ssend_");
  ++p2p_messages;
  p2p_bytes += fortran_bytes(c, t);
  f(b, c, t, d, g, m, e);
}
void
mpi_isend_(void *b, MPI_Fint *c, MPI_Fint *t, MPI_Fint *d, MPI_Fint *g,
           MPI_Fint *m, MPI_Fint *r, MPI_Fint *e)
{
  static fortran_isend f;
  if (!f)
    f = (fortran_isend)next("mpi_isend_");
  ++p2p_messages;
  p2p_bytes += fortran_bytes(c, t);
  f(b, c, t, d, g, m, r, e);
}

typedef void (*fortran_reduce_all)(void *, void *, MPI_Fint *, MPI_Fint *,
                                   MPI_Fint *, MPI_Fint *, MPI_Fint *);
void
mpi_allreduce_(void *sb, void *rb, MPI_Fint *c, MPI_Fint *t, MPI_Fint *o,
               MPI_Fint *m, MPI_Fint *e)
{
  static fortran_reduce_all f;
  if (!f)
    f = (fortran_reduce_all)next("mpi_allreduce_");
  collective(fortran_bytes(c, t));
  f(sb, rb, c, t, o, m, e);
}

typedef void (*fortran_reduce)(void *, void *, MPI_Fint *, MPI_Fint *,
                               MPI_Fint *, MPI_Fint *, MPI_Fint *, MPI_Fint *);
void
mpi_reduce_(void *sb, void *rb, MPI_Fint *c, MPI_Fint *t, MPI_Fint *o,
            MPI_Fint *root, MPI_Fint *m, MPI_Fint *e)
{
  static fortran_reduce f;
  if (!f)
    f = (fortran_reduce)next("mpi_reduce_");
  collective(fortran_bytes(c, t));
  f(sb, rb, c, t, o, root, m, e);
}

typedef void (*fortran_bcast)(void *, MPI_Fint *, MPI_Fint *, MPI_Fint *,
                              MPI_Fint *, MPI_Fint *);
void
mpi_bcast_(void *b, MPI_Fint *c, MPI_Fint *t, MPI_Fint *root, MPI_Fint *m,
           MPI_Fint *e)
{
  static fortran_bcast f;
  if (!f)
    f = (fortran_bcast)next("mpi_bcast_");
  collective(rank_of(MPI_Comm_f2c(*m)) == *root ? fortran_bytes(c, t) : 0);
  f(b, c, t, root, m, e);
}

typedef void (*fortran_alltoall)(void *, MPI_Fint *, MPI_Fint *, void *,
                                 MPI_Fint *, MPI_Fint *, MPI_Fint *,
                                 MPI_Fint *);
void
mpi_alltoall_(void *sb, MPI_Fint *sc, MPI_Fint *st, void *rb, MPI_Fint *rc,
              MPI_Fint *rt, MPI_Fint *m, MPI_Fint *e)
{
  static fortran_alltoall f;
  if (!f)
    f = (fortran_alltoall)next("mpi_alltoall_");
  collective(fortran_bytes(sc, st) * size_of(MPI_Comm_f2c(*m)));
  f(sb, sc, st, rb, rc, rt, m, e);
}

typedef void (*fortran_gather)(void *, MPI_Fint *, MPI_Fint *, void *,
                               MPI_Fint *, MPI_Fint *, MPI_Fint *, MPI_Fint *,
                               MPI_Fint *);
void
mpi_gather_(void *sb, MPI_Fint *sc, MPI_Fint *st, void *rb, MPI_Fint *rc,
            MPI_Fint *rt, MPI_Fint *root, MPI_Fint *m, MPI_Fint *e)
{
  static fortran_gather f;
  if (!f)
    f = (fortran_gather)next("mpi_gather_");
  collective(fortran_bytes(sc, st));
  f(sb, sc, st, rb, rc, rt, root, m, e);
}

typedef void (*fortran_reduce_scatter)(void *, void *, MPI_Fint *, MPI_Fint *,
                                       MPI_Fint *, MPI_Fint *, MPI_Fint *);
void
mpi_reduce_scatter_(void *sb, void *rb, MPI_Fint *rc, MPI_Fint *t, MPI_Fint *o,
                    MPI_Fint *m, MPI_Fint *e)
{
  static fortran_reduce_scatter f;
  if (!f)
    f = (fortran_reduce_scatter)next("mpi_reduce_scatter_");
  long long bytes = 0;
  for (int p = 0; p < size_of(MPI_Comm_f2c(*m)); ++p)
    bytes += bytes_of(rc[p], MPI_Type_f2c(*t));
  collective(bytes);
  f(sb, rb, rc, t, o, m, e);
}

typedef void (*fortran_barrier)(MPI_Fint *, MPI_Fint *);
void
mpi_barrier_(MPI_Fint *m, MPI_Fint *e)
{
  static fortran_barrier f;
  if (!f)
    f = (fortran_barrier)next("mpi_barrier_");
  collective(0);
  f(m, e);
}

/* ---- the report ---- */
int
MPI_Finalize(void)
{
  const char *path = getenv("MPI_TRAFFIC_OUTPUT");
  if (path)
    {
      FILE *out = fopen(path, "a");
      if (out)
        {
          fprintf(out,
                  "rank %d p2p_messages %lld p2p_bytes %lld collectives %lld "
                  "collective_bytes %lld\n",
                  rank_of(MPI_COMM_WORLD),
                  p2p_messages,
                  p2p_bytes,
                  collectives,
                  collective_bytes);
          fclose(out);
        }
    }
  return PMPI_Finalize();
}

/*
 * The two constants of the latency-bandwidth model t(n) = alpha + beta n of
 * one MPI message of n bytes, and the time of one small MPI_Allreduce,
 * measured between ranks 0 and 1 of MPI_COMM_WORLD (the others take part in
 * the all-reduces only).
 *
 * Point to point: ping-pong of n = 8 B ... 16 MiB (half the round trip),
 * in batches of as many round trips as fill about 0.2 s (at least 10), the
 * fastest batch of 5. All-reduce: 8 B (one double, as a norm or dot product
 * of Newton and GMRES) and 8 kB, batched the same way. Prints "p2p BYTES SECONDS" and "allreduce BYTES
 * SECONDS" lines (rank 0).
 */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

/* reps round trips of n bytes between ranks 0 and 1 */
static double
round_trips(const int rank, char *buffer, const int n, const int reps)
{
  const double start = MPI_Wtime();
  for (int k = 0; k < reps; ++k)
    if (rank == 0)
      {
        MPI_Send(buffer, n, MPI_CHAR, 1, 0, MPI_COMM_WORLD);
        MPI_Recv(buffer, n, MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      }
    else if (rank == 1)
      {
        MPI_Recv(buffer, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(buffer, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
      }
  return MPI_Wtime() - start;
}

static double
pingpong(const int rank, char *buffer, const int n)
{
  /* as many round trips as fill 0.2 s (rank 0's estimate from 10) */
  double t10  = round_trips(rank, buffer, n, 10);
  MPI_Bcast(&t10, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  const int reps = t10 > 0.2 ? 10 : (int)(10 * 0.2 / t10) + 10;
  double    best = 1e30;
  for (int batch = 0; batch < 5; ++batch)
    {
      MPI_Barrier(MPI_COMM_WORLD);
      const double t = round_trips(rank, buffer, n, reps) / reps / 2.;
      if (t < best)
        best = t;
    }
  return best;
}

static double
allreduce(double *in, double *out, const int count)
{
  double start = MPI_Wtime(), t10;
  for (int k = 0; k < 10; ++k)
    MPI_Allreduce(in, out, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  t10 = MPI_Wtime() - start;
  MPI_Bcast(&t10, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  const int reps = t10 > 0.2 ? 10 : (int)(10 * 0.2 / t10) + 10;
  double    best = 1e30;
  for (int batch = 0; batch < 5; ++batch)
    {
      MPI_Barrier(MPI_COMM_WORLD);
      start = MPI_Wtime();
      for (int k = 0; k < reps; ++k)
        MPI_Allreduce(in, out, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
      const double t = (MPI_Wtime() - start) / reps;
      if (t < best)
        best = t;
    }
  return best;
}

int
main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2)
    {
      if (rank == 0)
        fprintf(stderr, "pingpong needs at least 2 ranks\n");
      MPI_Finalize();
      return 1;
    }
  const int max_bytes = 16 << 20;
  char     *buffer    = malloc(max_bytes);
  for (int i = 0; i < max_bytes; ++i)
    buffer[i] = (char)i;
  for (int n = 8; n <= max_bytes; n *= 4)
    {
      const double t = pingpong(rank, buffer, n);
      if (rank == 0)
        printf("p2p %d %.6e\n", n, t);
    }
  double in[1024], out[1024];
  for (int i = 0; i < 1024; ++i)
    in[i] = rank + i;
  const int counts[] = {1, 1024};
  for (int k = 0; k < 2; ++k)
    {
      const double t = allreduce(in, out, counts[k]);
      if (rank == 0)
        printf("allreduce %d %.6e\n", (int)(8 * counts[k]), t);
    }
  free(buffer);
  MPI_Finalize();
  return 0;
}

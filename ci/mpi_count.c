/* MPI call counter for ci/bench-comm (a PMPI interposer, LD_PRELOADed):
 * counts the collective and point-to-point calls a crashsim run makes and
 * the bytes it sends, per rank, and prints one line per rank at
 * MPI_Finalize:
 *   mpi_count rank R: allreduce N bytes B | alltoall(v) N bytes B |
 *   p2p-send N bytes B | other-collective N
 * Only what the engine calls is wrapped; everything else goes to MPI as is.
 * Written for measurement, not linked into crashsim. */
#include <mpi.h>
#include <stdio.h>

static long n_allreduce, b_allreduce, n_alltoall, b_alltoall, n_send, b_send, n_other;

static long bytes(int count, MPI_Datatype t) {
    int size = 0;
    PMPI_Type_size(t, &size);
    return (long)count * size;
}

int MPI_Allreduce(const void *s, void *r, int c, MPI_Datatype t, MPI_Op op, MPI_Comm comm) {
    n_allreduce++;
    b_allreduce += bytes(c, t);
    return PMPI_Allreduce(s, r, c, t, op, comm);
}

int MPI_Alltoall(const void *s, int sc, MPI_Datatype st, void *r, int rc, MPI_Datatype rt,
                 MPI_Comm comm) {
    int n = 0;
    PMPI_Comm_size(comm, &n);
    n_alltoall++;
    b_alltoall += bytes(sc, st) * n;
    return PMPI_Alltoall(s, sc, st, r, rc, rt, comm);
}

int MPI_Alltoallv(const void *s, const int *sc, const int *sd, MPI_Datatype st, void *r,
                  const int *rc, const int *rd, MPI_Datatype rt, MPI_Comm comm) {
    int n = 0;
    PMPI_Comm_size(comm, &n);
    n_alltoall++;
    for (int i = 0; i < n; i++) b_alltoall += bytes(sc[i], st);
    return PMPI_Alltoallv(s, sc, sd, st, r, rc, rd, rt, comm);
}

int MPI_Send(const void *b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm) {
    n_send++;
    b_send += bytes(c, t);
    return PMPI_Send(b, c, t, d, tag, comm);
}

int MPI_Isend(const void *b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm,
              MPI_Request *req) {
    n_send++;
    b_send += bytes(c, t);
    return PMPI_Isend(b, c, t, d, tag, comm, req);
}

int MPI_Sendrecv(const void *sb, int sc, MPI_Datatype st, int d, int stag, void *rb, int rc,
                 MPI_Datatype rt, int src, int rtag, MPI_Comm comm, MPI_Status *status) {
    n_send++;
    b_send += bytes(sc, st);
    return PMPI_Sendrecv(sb, sc, st, d, stag, rb, rc, rt, src, rtag, comm, status);
}

int MPI_Bcast(void *b, int c, MPI_Datatype t, int root, MPI_Comm comm) {
    n_other++;
    return PMPI_Bcast(b, c, t, root, comm);
}

int MPI_Allgather(const void *s, int sc, MPI_Datatype st, void *r, int rc, MPI_Datatype rt,
                  MPI_Comm comm) {
    n_other++;
    return PMPI_Allgather(s, sc, st, r, rc, rt, comm);
}

int MPI_Allgatherv(const void *s, int sc, MPI_Datatype st, void *r, const int *rc,
                   const int *rd, MPI_Datatype rt, MPI_Comm comm) {
    n_other++;
    return PMPI_Allgatherv(s, sc, st, r, rc, rd, rt, comm);
}

int MPI_Barrier(MPI_Comm comm) {
    n_other++;
    return PMPI_Barrier(comm);
}

int MPI_Finalize(void) {
    int rank = 0;
    PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
    fprintf(stderr,
            "mpi_count rank %d: allreduce %ld bytes %ld | alltoall(v) %ld bytes %ld | p2p-send %ld "
            "bytes %ld | other-collective %ld\n",
            rank, n_allreduce, b_allreduce, n_alltoall, b_alltoall, n_send, b_send, n_other);
    return PMPI_Finalize();
}

/* Message costs for ci/bench-comm: ping-pong time between ranks 0 and 1
 * (half the round trip) for messages of 8 B to 8 MiB, and the time of an
 * 8-byte MPI_Allreduce (the time step's global minimum), on the machine
 * it runs on. Written for measurement, not linked into crashsim. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    char *buf = calloc(1 << 23, 1);
    if (rank == 0) printf("%-12s %14s %12s\n", "bytes", "one-way (us)", "MB/s");
    for (long n = 8; n <= (1 << 23); n *= 8) {
        int reps = n < 65536 ? 2000 : 50;
        MPI_Barrier(MPI_COMM_WORLD);
        double t0 = MPI_Wtime();
        for (int i = 0; i < reps && rank < 2; i++) {
            if (rank == 0) {
                MPI_Send(buf, (int)n, MPI_BYTE, 1, 0, MPI_COMM_WORLD);
                MPI_Recv(buf, (int)n, MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            } else {
                MPI_Recv(buf, (int)n, MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Send(buf, (int)n, MPI_BYTE, 0, 0, MPI_COMM_WORLD);
            }
        }
        double t = (MPI_Wtime() - t0) / reps / 2.0;
        if (rank == 0) printf("%-12ld %14.2f %12.1f\n", n, t * 1e6, n / t / 1e6);
    }
    double x = 1.0, y;
    int reps = 5000;
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    for (int i = 0; i < reps; i++) MPI_Allreduce(&x, &y, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    double t = (MPI_Wtime() - t0) / reps;
    if (rank == 0) printf("allreduce of 8 B on %d ranks: %.2f us\n", size, t * 1e6);
    free(buf);
    MPI_Finalize();
    return 0;
}

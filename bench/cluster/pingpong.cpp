// MPI's cost on this machine for the cluster's scale model (model.py): the round trip of a
// message of each size between ranks 0 and 1, as rank 0's answers and the ranks' requests go.
//   mpirun -np 2 pingpong > latency.json
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) std::printf("{\"round_trip_seconds\": {");
    bool first = true;
    for (const int size : {64, 1024, 16384, 262144, 4194304}) {
        std::vector<char> buffer(std::size_t(size), 1);
        const int repeat = size > 100000 ? 50 : 2000;
        MPI_Barrier(MPI_COMM_WORLD);
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < repeat; ++i) {
            if (rank == 0) {
                MPI_Send(buffer.data(), size, MPI_CHAR, 1, 0, MPI_COMM_WORLD);
                MPI_Recv(buffer.data(), size, MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            } else if (rank == 1) {
                MPI_Recv(buffer.data(), size, MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Send(buffer.data(), size, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
            }
        }
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (rank == 0) std::printf("%s\"%d\": %.6g", first ? "" : ", ", size, s / repeat);
        first = false;
    }
    if (rank == 0) std::printf("}}\n");
    MPI_Finalize();
    return 0;
}

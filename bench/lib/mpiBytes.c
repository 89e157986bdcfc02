/*---------------------------------------------------------------------------*\
  impactFoam bench: the bytes an MPI rank sends
-------------------------------------------------------------------------------
  A library to LD_PRELOAD into an Open MPI run: it counts the bytes and the
  messages each rank sends point to point (MPI_Send, Isend, Bsend, Ssend:
  OpenFOAM's processor-patch exchanges and its reductions) and its
  MPI_Allreduce calls, and prints one line per rank at MPI_Finalize:
      mpiBytes rank <r>: sent <bytes> bytes in <n> messages; allreduce <n>
  Built by bench/impactCases with gcc against the system's libmpi.so.40.
  Open MPI's handles are pointers, so no mpi.h is needed (Debian's
  openfoam package does not pull libopenmpi-dev in).
\*---------------------------------------------------------------------------*/

#include <stdio.h>

typedef void* handle;
extern char ompi_mpi_comm_world;

int PMPI_Type_size(handle, int*);
int PMPI_Comm_rank(handle, int*);
int PMPI_Send(const void*, int, handle, int, int, handle);
int PMPI_Isend(const void*, int, handle, int, int, handle, handle*);
int PMPI_Bsend(const void*, int, handle, int, int, handle);
int PMPI_Ssend(const void*, int, handle, int, int, handle);
int PMPI_Allreduce(const void*, void*, int, handle, handle, handle);
int PMPI_Finalize(void);

static long long nBytes = 0, nMessages = 0, nAllreduce = 0;

static void count(int n, handle type)
{
    int size;
    PMPI_Type_size(type, &size);
    nBytes += (long long)n*size;
    nMessages++;
}

int MPI_Send(const void* b, int n, handle t, int d, int tag, handle c)
{
    count(n, t);
    return PMPI_Send(b, n, t, d, tag, c);
}

int MPI_Isend
(
    const void* b, int n, handle t, int d, int tag, handle c, handle* r
)
{
    count(n, t);
    return PMPI_Isend(b, n, t, d, tag, c, r);
}

int MPI_Bsend(const void* b, int n, handle t, int d, int tag, handle c)
{
    count(n, t);
    return PMPI_Bsend(b, n, t, d, tag, c);
}

int MPI_Ssend(const void* b, int n, handle t, int d, int tag, handle c)
{
    count(n, t);
    return PMPI_Ssend(b, n, t, d, tag, c);
}

int MPI_Allreduce
(
    const void* s, void* r, int n, handle t, handle op, handle c
)
{
    nAllreduce++;
    return PMPI_Allreduce(s, r, n, t, op, c);
}

int MPI_Finalize(void)
{
    int rank;
    PMPI_Comm_rank(&ompi_mpi_comm_world, &rank);
    fprintf
    (
        stderr, "mpiBytes rank %d: sent %lld bytes in %lld messages;"
        " allreduce %lld\n", rank, nBytes, nMessages, nAllreduce
    );
    return PMPI_Finalize();
}

/* One MUMPS LDL^T factorization of K - sigma M, read from PETSc binary
 * files, under a chosen ordering and MUMPS controls: what bounds the solid
 * level's one factorization (issue 19). Prints one JSON line.
 *
 *   factor_study -f matrices.bin [-sigma s] [-ordering pord|amd|amf|qamd|metis]
 *                [-compress 0|3] [-cntl1 x] [-sym 1|2] [-blr eps] [-analysis_only]
 *
 * matrices.bin holds K then M (coremodal run ... -- -mat_view
 * binary:matrices.bin::append writes them first). With -sigma 0 only K is
 * factored. METIS's nested dissection is computed here (Debian's MUMPS was
 * built without it) and given to MUMPS as its pivot order (ICNTL(7) = 1). */
#include <dmumps_c.h>
#include <metis.h>
#include <petscmat.h>

#include <string.h>
#include <time.h>

#define ICNTL(I) icntl[(I)-1]
#define CNTL(I) cntl[(I)-1]
#define INFOG(I) infog[(I)-1]
#define RINFOG(I) rinfog[(I)-1]

static double seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static Mat load(PetscViewer v) {
    Mat A;
    MatCreate(PETSC_COMM_SELF, &A);
    MatSetType(A, MATSEQAIJ);
    MatLoad(A, v);
    return A;
}

/* METIS nested dissection of A's graph; MUMPS's PERM_IN(i) is the position
 * of variable i in the pivot order (1-based): METIS's iperm + 1. */
static MUMPS_INT* metis_order(PetscInt n, const PetscInt* ia, const PetscInt* ja) {
    idx_t* xadj = malloc((size_t)(n + 1) * sizeof(idx_t));
    idx_t* adj = malloc((size_t)ia[n] * sizeof(idx_t));
    idx_t m = 0, nn = n;
    xadj[0] = 0;
    for (PetscInt i = 0; i < n; i++) {
        for (PetscInt k = ia[i]; k < ia[i + 1]; k++)
            if (ja[k] != i) adj[m++] = ja[k];
        xadj[i + 1] = m;
    }
    idx_t options[METIS_NOPTIONS], *perm = malloc((size_t)n * sizeof(idx_t)), *iperm = malloc((size_t)n * sizeof(idx_t));
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    METIS_NodeND(&nn, xadj, adj, NULL, options, perm, iperm);
    MUMPS_INT* order = malloc((size_t)n * sizeof(MUMPS_INT));
    for (PetscInt i = 0; i < n; i++) order[i] = (MUMPS_INT)iperm[i] + 1;
    free(xadj), free(adj), free(perm), free(iperm);
    return order;
}

int main(int argc, char** argv) {
    PetscInitialize(&argc, &argv, NULL, NULL);
    char file[PETSC_MAX_PATH_LEN] = "", ordering[32] = "pord";
    PetscReal sigma = 0, cntl1 = -1, blr = 0;
    PetscInt compress = -3, sym = 2;
    PetscBool analysis_only = PETSC_FALSE;
    PetscOptionsGetString(NULL, NULL, "-f", file, sizeof file, NULL);
    PetscOptionsGetString(NULL, NULL, "-ordering", ordering, sizeof ordering, NULL);
    PetscOptionsGetReal(NULL, NULL, "-sigma", &sigma, NULL);
    PetscOptionsGetReal(NULL, NULL, "-cntl1", &cntl1, NULL);
    PetscOptionsGetReal(NULL, NULL, "-blr", &blr, NULL);
    PetscOptionsGetInt(NULL, NULL, "-compress", &compress, NULL);
    PetscOptionsGetInt(NULL, NULL, "-sym", &sym, NULL);
    PetscOptionsGetBool(NULL, NULL, "-analysis_only", &analysis_only, NULL);

    PetscViewer v;
    PetscViewerBinaryOpen(PETSC_COMM_SELF, file, FILE_MODE_READ, &v);
    Mat A = load(v);
    if (sigma != 0) {
        Mat M = load(v);
        MatAXPY(A, -sigma, M, SAME_NONZERO_PATTERN);
        MatDestroy(&M);
    }
    PetscViewerDestroy(&v);

    PetscInt n;
    const PetscInt *ia, *ja;
    PetscBool done;
    const PetscScalar* a;
    MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done);
    MatSeqAIJGetArrayRead(A, &a);
    MUMPS_INT8 nz = 0;
    for (PetscInt i = 0; i < n; i++)
        for (PetscInt k = ia[i]; k < ia[i + 1]; k++) nz += ja[k] >= i;
    MUMPS_INT *irn = malloc((size_t)nz * sizeof(MUMPS_INT)), *jcn = malloc((size_t)nz * sizeof(MUMPS_INT));
    double* val = malloc((size_t)nz * sizeof(double));
    nz = 0;
    for (PetscInt i = 0; i < n; i++)
        for (PetscInt k = ia[i]; k < ia[i + 1]; k++)
            if (ja[k] >= i) irn[nz] = i + 1, jcn[nz] = ja[k] + 1, val[nz++] = a[k];

    double t0 = seconds();
    MUMPS_INT* order = strcmp(ordering, "metis") == 0 ? metis_order(n, ia, ja) : NULL;
    const double ordering_s = seconds() - t0;

    DMUMPS_STRUC_C id;
    memset(&id, 0, sizeof id);
    id.comm_fortran = -987654; /* MUMPS's code for MPI_COMM_WORLD */
    id.par = 1;
    id.sym = (MUMPS_INT)sym;
    id.job = -1;
    dmumps_c(&id);
    id.ICNTL(1) = id.ICNTL(2) = id.ICNTL(3) = -1;
    id.ICNTL(4) = 0;
    id.ICNTL(13) = 1; /* as coremodal: no ScaLAPACK root, the count in parallel */
    id.ICNTL(15) = (MUMPS_INT)compress; /* PETSc passes -3: three unknowns a node */
    if (cntl1 >= 0) id.CNTL(1) = cntl1;
    if (blr > 0) id.ICNTL(35) = 2, id.CNTL(7) = blr;
    const struct { const char* name; int icntl7; } orderings[] = {{"amd", 0}, {"amf", 2}, {"pord", 4}, {"qamd", 6}};
    id.ICNTL(7) = 4;
    for (size_t i = 0; i < sizeof orderings / sizeof orderings[0]; i++)
        if (strcmp(ordering, orderings[i].name) == 0) id.ICNTL(7) = orderings[i].icntl7;
    if (order) id.ICNTL(7) = 1, id.perm_in = order;
    id.n = (MUMPS_INT)n, id.nnz = nz, id.irn = irn, id.jcn = jcn, id.a = val;

    t0 = seconds();
    id.job = 1;
    dmumps_c(&id);
    const double analysis_s = seconds() - t0;
    double numeric_s = 0;
    if (!analysis_only && id.INFOG(1) >= 0) {
        t0 = seconds();
        id.job = 2;
        dmumps_c(&id);
        numeric_s = seconds() - t0;
    }
    printf("{\"n\": %d, \"ordering\": \"%s\", \"compress\": %d, \"sym\": %d, \"cntl1\": %g, \"blr\": %g, "
           "\"ordering_s\": %.3f, \"analysis_s\": %.3f, \"numeric_s\": %.3f, \"flops\": %.4e, \"factor_entries\": %lld, "
           "\"largest_front\": %d, \"negative_pivots\": %d, \"delayed_pivots\": %d, \"error\": %d}\n",
           (int)n, ordering, (int)compress, (int)sym, cntl1, blr, ordering_s, analysis_s, numeric_s, id.RINFOG(1),
           (long long)id.INFOG(20), id.INFOG(5), analysis_only ? -1 : id.INFOG(12), id.INFOG(13), id.INFOG(1));
    id.job = -2;
    dmumps_c(&id);
    free(irn), free(jcn), free(val), free(order);
    MatSeqAIJRestoreArrayRead(A, &a);
    MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done);
    MatDestroy(&A);
    PetscFinalize();
    return 0;
}

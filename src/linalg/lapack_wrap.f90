!> Checked wrappers around the few LAPACK routines bifilar uses, and a written-out Cholesky
!! factorisation for the smallest symmetric positive definite systems.
!!
!! Least squares: la_lstsq (DGELS, QR) and la_svd (DGESVD, singular values and right
!! singular vectors), for the identification's Levenberg-Marquardt steps and covariances.
!! The inertia tensor (analysis tensor): la_syev (DSYEV, a symmetric matrix's eigenvalues
!! and eigenvectors), la_eigv (DGEEV with right eigenvectors: the normal modes of a hang),
!! la_chol and la_tri_solve (DPOTRF, DTRTRS: whitening by a covariance's Cholesky factor).
!!
!! Each wrapper checks the shapes of its arguments, calls LAPACK through an explicit
!! interface, and maps INFO to a status_t with a message naming the routine and the cause.
!! No wrapper stops the program.
!!
!! Symmetric positive definite systems of order n <= SMALL_N (the 4 x 4 system of the
!! independent accelerations of eq. (38), solved at every right-hand side) are factored by
!! la_small_chol / la_small_chol_solve: LAPACK's unblocked Cholesky algorithm (DPOTF2, lower:
!! a_jj = sqrt(a_jj - sum_k<j l_jk^2), l_ij = (a_ij - sum_k<j l_ik l_jk)/l_jj; DPOTRS: forward
!! then backward substitution) written out, without the call overhead (calls into reference
!! BLAS for a few dozen operations) that costs more than the arithmetic at n = 4.  Larger
!! systems go to LAPACK.
module lapack_wrap
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    implicit none
    private

    public :: la_solve, la_lu_factor, la_lu_solve, la_lu_solve_many, la_eig, la_geig
    public :: la_small_chol, la_small_chol_solve, la_small_lu_solve, la_small_inverse
    public :: la_zlu_factor, la_zlu_solve
    public :: la_lstsq, la_svd
    public :: la_syev, la_eigv, la_chol, la_tri_solve

    integer, parameter, public :: SMALL_N = 8   !! largest order of la_small_chol

    interface
        subroutine dgetf2(m, n, a, lda, ipiv, info)
            import :: dp
            integer, intent(in) :: m, n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: ipiv(*), info
        end subroutine dgetf2
        subroutine dgetrf(m, n, a, lda, ipiv, info)
            import :: dp
            integer, intent(in) :: m, n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: ipiv(*), info
        end subroutine dgetrf
        subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: trans
            integer, intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(in) :: a(lda, *)
            integer, intent(in) :: ipiv(*)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dgetrs
        subroutine dgeev(jobvl, jobvr, n, a, lda, wr, wi, vl, ldvl, vr, ldvr, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: jobvl, jobvr
            integer, intent(in) :: n, lda, ldvl, ldvr, lwork
            real(dp), intent(inout) :: a(lda, *)
            real(dp), intent(out) :: wr(*), wi(*), vl(ldvl, *), vr(ldvr, *), work(*)
            integer, intent(out) :: info
        end subroutine dgeev
        subroutine dggev(jobvl, jobvr, n, a, lda, b, ldb, alphar, alphai, beta, vl, ldvl, vr, &
                         ldvr, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: jobvl, jobvr
            integer, intent(in) :: n, lda, ldb, ldvl, ldvr, lwork
            real(dp), intent(inout) :: a(lda, *), b(ldb, *)
            real(dp), intent(out) :: alphar(*), alphai(*), beta(*), vl(ldvl, *), vr(ldvr, *)
            real(dp), intent(out) :: work(*)
            integer, intent(out) :: info
        end subroutine dggev
        subroutine dgels(trans, m, n, nrhs, a, lda, b, ldb, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: trans
            integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
            real(dp), intent(inout) :: a(lda, *), b(ldb, *)
            real(dp), intent(out) :: work(*)
            integer, intent(out) :: info
        end subroutine dgels
        subroutine dgesvd(jobu, jobvt, m, n, a, lda, s, u, ldu, vt, ldvt, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: jobu, jobvt
            integer, intent(in) :: m, n, lda, ldu, ldvt, lwork
            real(dp), intent(inout) :: a(lda, *)
            real(dp), intent(out) :: s(*), u(ldu, *), vt(ldvt, *), work(*)
            integer, intent(out) :: info
        end subroutine dgesvd
        subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: jobz, uplo
            integer, intent(in) :: n, lda, lwork
            real(dp), intent(inout) :: a(lda, *)
            real(dp), intent(out) :: w(*), work(*)
            integer, intent(out) :: info
        end subroutine dsyev
        subroutine dpotrf(uplo, n, a, lda, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: info
        end subroutine dpotrf
        subroutine dtrtrs(uplo, trans, diag, n, nrhs, a, lda, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: uplo, trans, diag
            integer, intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(in) :: a(lda, *)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dtrtrs
        subroutine zgetrf(m, n, a, lda, ipiv, info)
            import :: dp
            integer, intent(in) :: m, n, lda
            complex(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: ipiv(*), info
        end subroutine zgetrf
        subroutine zgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: trans
            integer, intent(in) :: n, nrhs, lda, ldb
            complex(dp), intent(in) :: a(lda, *)
            integer, intent(in) :: ipiv(*)
            complex(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine zgetrs
    end interface

contains

    !> Solve the small square system A x = b in place: LU with partial pivoting by LAPACK's
    !! unblocked DGETF2 (for n of a few, the blocked recursive DGETRF/DGESV costs several
    !! times more), then DGETRS.
    !!
    !! a   [in,out] real(dp)(n,n): the matrix; overwritten by its LU factors.
    !! b   [in,out] real(dp)(n):   right-hand side on entry, solution x on return.
    !! stat [out]: ERR_NUMERIC when the shapes disagree (INFO would be < 0) or
    !!             when U(i,i) is exactly zero (INFO = i > 0: A is singular).
    subroutine la_solve(a, b, stat)
        real(dp), intent(inout) :: a(:, :)
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: stat
        integer :: n, info
        integer :: ipiv(size(a, 1))
        character(len=80) :: buf
        n = size(a, 1)
        if (size(a, 2) /= n .or. size(b) /= n) then
            call set_error(stat, ERR_NUMERIC, 'la_solve: matrix and right-hand side shapes disagree')
            return
        end if
        call dgetf2(n, n, a, n, ipiv, info)
        if (info == 0) call dgetrs('N', n, 1, a, n, ipiv, b, n, info)
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_solve (dgetf2): singular matrix, U(i,i) = 0 at i = ', info
            if (info < 0) write (buf, '(a,i0)') 'la_solve (dgetf2/dgetrs): illegal argument ', &
                -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_solve

    !> Cholesky factorisation A = L L^T of a small symmetric positive definite matrix,
    !! DPOTF2's algorithm written out (see the module header); only the lower triangle of a
    !! is read.  Explicit shapes, so that a constant n lets the compiler unroll it.
    !!
    !! n    [in]     integer:       order, 1 <= n <= SMALL_N.
    !! a    [in,out] real(dp)(n,n): the matrix (lower triangle); overwritten by L (lower
    !!                              triangle; the strict upper triangle is not referenced).
    !! stat [out]: ERR_NUMERIC when n is out of range or A is not positive definite (as
    !!             DPOTF2's INFO = j > 0: the leading minor of order j is not positive).
    pure subroutine la_small_chol(n, a, stat)
        integer, intent(in) :: n
        real(dp), intent(inout) :: a(n, n)
        type(status_t), intent(out) :: stat
        real(dp) :: ajj
        integer :: i, j, k
        character(len=100) :: buf
        if (n > SMALL_N .or. n < 1) then
            call set_error(stat, ERR_NUMERIC, 'la_small_chol: order n out of 1 ... SMALL_N')
            return
        end if
        !GCC$ unroll 8
        do j = 1, n
            ajj = a(j, j)
            !GCC$ unroll 8
            do k = 1, j - 1
                ajj = ajj - a(j, k)*a(j, k)
            end do
            if (.not. (ajj > 0.0_dp)) then
                write (buf, '(a,i0,a)') 'la_small_chol: matrix not positive definite (leading '// &
                    'minor of order ', j, ')'
                call set_error(stat, ERR_NUMERIC, trim(buf))
                return
            end if
            ajj = sqrt(ajj)
            a(j, j) = ajj
            !GCC$ unroll 8
            do i = j + 1, n
                !GCC$ unroll 8
                do k = 1, j - 1
                    a(i, j) = a(i, j) - a(i, k)*a(j, k)
                end do
                a(i, j) = a(i, j)/ajj
            end do
        end do
    end subroutine la_small_chol

    !> Solve A x = b in place with the factor L from la_small_chol (DPOTRS's algorithm:
    !! L y = b, then L^T x = y).
    !!
    !! n [in]     integer:       order.
    !! l [in]     real(dp)(n,n): the factor from la_small_chol (lower triangle).
    !! b [in,out] real(dp)(n):   right-hand side on entry, solution on return.
    pure subroutine la_small_chol_solve(n, l, b)
        integer, intent(in) :: n
        real(dp), intent(in) :: l(n, n)
        real(dp), intent(inout) :: b(n)
        integer :: i, k
        !GCC$ unroll 8
        do i = 1, n
            !GCC$ unroll 8
            do k = 1, i - 1
                b(i) = b(i) - l(i, k)*b(k)
            end do
            b(i) = b(i)/l(i, i)
        end do
        !GCC$ unroll 8
        do i = n, 1, -1
            !GCC$ unroll 8
            do k = i + 1, n
                b(i) = b(i) - l(k, i)*b(k)
            end do
            b(i) = b(i)/l(i, i)
        end do
    end subroutine la_small_chol_solve

    !> LU factorisation with partial pivoting of a square matrix (LAPACK DGETRF).
    !!
    !! a    [in,out] real(dp)(n,n): the matrix; overwritten by L and U.
    !! ipiv [out]    integer(n):    pivot indices.
    !! stat [out]: ERR_NUMERIC when the shapes disagree or U is exactly singular (INFO > 0).
    subroutine la_lu_factor(a, ipiv, stat)
        real(dp), intent(inout) :: a(:, :)
        integer, intent(out) :: ipiv(:)
        type(status_t), intent(out) :: stat
        integer :: n, info
        character(len=80) :: buf
        n = size(a, 1)
        if (size(a, 2) /= n .or. size(ipiv) < n) then
            ipiv = 0
            call set_error(stat, ERR_NUMERIC, 'la_lu_factor: matrix is not square or ipiv too short')
            return
        end if
        call dgetrf(n, n, a, n, ipiv, info)
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_lu_factor (dgetrf): singular matrix, U(i,i) = 0 at i = ', info
            if (info < 0) write (buf, '(a,i0)') 'la_lu_factor (dgetrf): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_lu_factor

    !> Solve A x = b with the factors from la_lu_factor (LAPACK DGETRS, no transpose).
    !!
    !! lu   [in]     real(dp)(n,n): factors from la_lu_factor.
    !! ipiv [in]     integer(n):    pivots from la_lu_factor.
    !! b    [in,out] real(dp)(n):   right-hand side on entry, solution on return.
    !! stat [out]: ERR_NUMERIC when the shapes disagree.
    subroutine la_lu_solve(lu, ipiv, b, stat)
        real(dp), intent(in) :: lu(:, :)
        integer, intent(in) :: ipiv(:)
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: stat
        integer :: n, info
        n = size(lu, 1)
        if (size(lu, 2) /= n .or. size(b) /= n .or. size(ipiv) < n) then
            call set_error(stat, ERR_NUMERIC, 'la_lu_solve: factor, pivot and vector shapes disagree')
            return
        end if
        call dgetrs('N', n, 1, lu, n, ipiv, b, n, info)
        if (info /= 0) call set_error(stat, ERR_NUMERIC, 'la_lu_solve (dgetrs): illegal argument')
    end subroutine la_lu_solve

    !> Solve A x = b with the factors and pivots of la_lu_factor, written out (for small
    !! systems, where LAPACK's call costs more than the arithmetic): the row interchanges,
    !! then L (unit lower) and U by columns.
    !!
    !! lu   [in]     real(dp)(n,n): factors from la_lu_factor.
    !! ipiv [in]     integer(n):    pivots from la_lu_factor.
    !! b    [in,out] real(dp)(n):   right-hand side on entry, solution on return.
    pure subroutine la_small_lu_solve(lu, ipiv, b)
        real(dp), intent(in) :: lu(:, :)
        integer, intent(in) :: ipiv(:)
        real(dp), intent(inout) :: b(:)
        real(dp) :: t
        integer :: n, i, j
        n = size(b)
        do i = 1, n
            j = ipiv(i)
            if (j /= i) then
                t = b(i)
                b(i) = b(j)
                b(j) = t
            end if
        end do
        do j = 1, n - 1
            t = b(j)
            if (t /= 0.0_dp) b(j + 1:n) = b(j + 1:n) - t*lu(j + 1:n, j)
        end do
        do j = n, 1, -1
            b(j) = b(j)/lu(j, j)
            t = b(j)
            if (t /= 0.0_dp) b(1:j - 1) = b(1:j - 1) - t*lu(1:j - 1, j)
        end do
    end subroutine la_small_lu_solve

    !> The inverse of a small square matrix, written out (for orders where LAPACK's DGETRF
    !! and DGETRS cost more in calls than in arithmetic): Gauss-Jordan elimination in place
    !! with partial pivoting by rows, each elimination a rank-one update by columns; the
    !! row interchanges undone at the end as interchanges of columns.
    !!
    !! n    [in]  integer:       order, >= 1.
    !! a    [in]  real(dp)(n,n): the matrix.
    !! ainv [out] real(dp)(n,n): its inverse.
    !! stat [out]: ERR_NUMERIC when a pivot is exactly 0 (A singular), naming the column.
    pure subroutine la_small_inverse(n, a, ainv, stat)
        integer, intent(in) :: n
        real(dp), intent(in) :: a(n, n)
        real(dp), intent(out) :: ainv(n, n)
        type(status_t), intent(out) :: stat
        real(dp) :: f(n), t, d
        integer :: piv(n), i, j, k, ip
        character(len=80) :: buf
        stat%code = 0
        ainv = a
        do k = 1, n
            ip = k - 1 + maxloc(abs(ainv(k:n, k)), 1)
            piv(k) = ip
            if (.not. (abs(ainv(ip, k)) > 0.0_dp)) then
                write (buf, '(a,i0)') 'la_small_inverse: singular matrix, pivot 0 in column ', k
                call set_error(stat, ERR_NUMERIC, trim(buf))
                return
            end if
            if (ip /= k) then
                do j = 1, n
                    t = ainv(k, j)
                    ainv(k, j) = ainv(ip, j)
                    ainv(ip, j) = t
                end do
            end if
            d = 1.0_dp/ainv(k, k)
            f = ainv(:, k)
            f(k) = 0.0_dp
            ainv(:, k) = 0.0_dp
            ainv(k, k) = 1.0_dp
            do j = 1, n
                ainv(k, j) = ainv(k, j)*d
            end do
            do j = 1, n
                t = ainv(k, j)
                do i = 1, n
                    ainv(i, j) = ainv(i, j) - f(i)*t
                end do
            end do
        end do
        do k = n - 1, 1, -1
            ip = piv(k)
            if (ip == k) cycle
            f = ainv(:, k)
            ainv(:, k) = ainv(:, ip)
            ainv(:, ip) = f
        end do
    end subroutine la_small_inverse

    !> Solve A X = B for several right-hand sides with the factors from la_lu_factor
    !! (LAPACK DGETRS, no transpose, one call).
    !!
    !! lu   [in]     real(dp)(n,n):    factors from la_lu_factor.
    !! ipiv [in]     integer(n):       pivots from la_lu_factor.
    !! b    [in,out] real(dp)(n,nrhs): right-hand sides on entry, solutions on return.
    !! stat [out]: ERR_NUMERIC when the shapes disagree.
    subroutine la_lu_solve_many(lu, ipiv, b, stat)
        real(dp), intent(in) :: lu(:, :)
        integer, intent(in) :: ipiv(:)
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: stat
        integer :: n, info
        n = size(lu, 1)
        if (size(lu, 2) /= n .or. size(b, 1) /= n .or. size(ipiv) < n) then
            call set_error(stat, ERR_NUMERIC, 'la_lu_solve_many: factor, pivot and '// &
                           'right-hand side shapes disagree')
            return
        end if
        call dgetrs('N', n, size(b, 2), lu, n, ipiv, b, n, info)
        if (info /= 0) call set_error(stat, ERR_NUMERIC, 'la_lu_solve_many (dgetrs): illegal argument')
    end subroutine la_lu_solve_many

    !> LU factorisation with partial pivoting of a complex square matrix (LAPACK ZGETRF).
    !!
    !! a    [in,out] complex(dp)(n,n): the matrix; overwritten by L and U.
    !! ipiv [out]    integer(n):       pivot indices.
    !! stat [out]: ERR_NUMERIC when the shapes disagree or U is exactly singular (INFO > 0).
    subroutine la_zlu_factor(a, ipiv, stat)
        complex(dp), intent(inout) :: a(:, :)
        integer, intent(out) :: ipiv(:)
        type(status_t), intent(out) :: stat
        integer :: n, info
        character(len=80) :: buf
        n = size(a, 1)
        if (size(a, 2) /= n .or. size(ipiv) < n) then
            ipiv = 0
            call set_error(stat, ERR_NUMERIC, 'la_zlu_factor: matrix is not square or ipiv '// &
                'too short')
            return
        end if
        call zgetrf(n, n, a, n, ipiv, info)
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_zlu_factor (zgetrf): singular matrix, U(i,i) = 0 at '// &
                'i = ', info
            if (info < 0) write (buf, '(a,i0)') 'la_zlu_factor (zgetrf): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_zlu_factor

    !> Solve the complex system A x = b with the factors from la_zlu_factor (LAPACK ZGETRS,
    !! no transpose).
    !!
    !! lu   [in]     complex(dp)(n,n): factors from la_zlu_factor.
    !! ipiv [in]     integer(n):       pivots from la_zlu_factor.
    !! b    [in,out] complex(dp)(n):   right-hand side on entry, solution on return.
    !! stat [out]: ERR_NUMERIC when the shapes disagree.
    subroutine la_zlu_solve(lu, ipiv, b, stat)
        complex(dp), intent(in) :: lu(:, :)
        integer, intent(in) :: ipiv(:)
        complex(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: stat
        integer :: n, info
        n = size(lu, 1)
        if (size(lu, 2) /= n .or. size(b) /= n .or. size(ipiv) < n) then
            call set_error(stat, ERR_NUMERIC, 'la_zlu_solve: factor, pivot and vector shapes '// &
                'disagree')
            return
        end if
        call zgetrs('N', n, 1, lu, n, ipiv, b, n, info)
        if (info /= 0) call set_error(stat, ERR_NUMERIC, 'la_zlu_solve (zgetrs): illegal argument')
    end subroutine la_zlu_solve

    !> Eigenvalues of a general real square matrix (LAPACK DGEEV, no eigenvectors).
    !!
    !! a    [in]  real(dp)(n,n): the matrix (not changed: a copy is factored).
    !! lam  [out] complex(dp)(n): eigenvalues; conjugate pairs are adjacent, positive
    !!            imaginary part first (built from DGEEV's WR and WI).
    !! stat [out]: ERR_NUMERIC on a shape mismatch or when the QR algorithm fails to
    !!             converge (INFO > 0: eigenvalues INFO+1:N would be the converged ones).
    subroutine la_eig(a, lam, stat)
        real(dp), intent(in) :: a(:, :)
        complex(dp), intent(out) :: lam(:)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: acopy(:, :), work(:)
        real(dp) :: wr(size(a, 1)), wi(size(a, 1)), vl(1, 1), vr(1, 1), wquery(1)
        integer :: n, info, lwork
        character(len=80) :: buf
        n = size(a, 1)
        lam = (0.0_dp, 0.0_dp)
        if (size(a, 2) /= n .or. size(lam) /= n) then
            call set_error(stat, ERR_NUMERIC, 'la_eig: matrix is not square or lam has the wrong size')
            return
        end if
        allocate (acopy(n, n))
        acopy(:, :) = a
        call dgeev('N', 'N', n, acopy, n, wr, wi, vl, 1, vr, 1, wquery, -1, info)
        lwork = max(1, int(wquery(1)))
        allocate (work(lwork))
        call dgeev('N', 'N', n, acopy, n, wr, wi, vl, 1, vr, 1, work, lwork, info)
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_eig (dgeev): QR algorithm failed to converge, info = ', info
            if (info < 0) write (buf, '(a,i0)') 'la_eig (dgeev): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
            return
        end if
        lam = cmplx(wr, wi, kind=dp)
    end subroutine la_eig

    !> Generalized eigenvalues of the pencil (A, B): A v = lambda B v (LAPACK DGGEV, QZ,
    !! no eigenvectors).  The pencil is never reduced to B^-1 A, so eigenvalues of very
    !! different size are computed with a backward error relative to |A| and |B|.
    !!
    !! a, b [in]  real(dp)(n,n): the pencil (not changed: copies are reduced).
    !! alpha [out] complex(dp)(n), beta [out] real(dp)(n): lambda = alpha/beta; beta = 0 for
    !!             an infinite eigenvalue.  Conjugate pairs are adjacent.
    !! stat [out]: ERR_NUMERIC on a shape mismatch or when QZ fails (INFO > 0).
    subroutine la_geig(a, b, alpha, beta, stat)
        real(dp), intent(in) :: a(:, :), b(:, :)
        complex(dp), intent(out) :: alpha(:)
        real(dp), intent(out) :: beta(:)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: ac(:, :), bc(:, :), work(:)
        real(dp) :: ar(size(a, 1)), ai(size(a, 1)), vl(1, 1), vr(1, 1), wquery(1)
        integer :: n, info, lwork
        character(len=80) :: buf
        n = size(a, 1)
        alpha = (0.0_dp, 0.0_dp)
        beta = 0.0_dp
        if (size(a, 2) /= n .or. any(shape(b) /= [n, n]) .or. size(alpha) /= n .or. &
            size(beta) /= n) then
            call set_error(stat, ERR_NUMERIC, 'la_geig: pencil or result shapes disagree')
            return
        end if
        allocate (ac(n, n), bc(n, n))
        ac(:, :) = a
        bc(:, :) = b
        call dggev('N', 'N', n, ac, n, bc, n, ar, ai, beta, vl, 1, vr, 1, wquery, -1, info)
        lwork = max(8*n, int(wquery(1)))
        allocate (work(lwork))
        call dggev('N', 'N', n, ac, n, bc, n, ar, ai, beta, vl, 1, vr, 1, work, lwork, info)
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_geig (dggev): QZ iteration failed, info = ', info
            if (info < 0) write (buf, '(a,i0)') 'la_geig (dggev): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
            return
        end if
        alpha = cmplx(ar, ai, kind=dp)
    end subroutine la_geig

    !> Linear least squares: x minimising ||A x - b||_2 for an m x n matrix of full column
    !! rank, m >= n (LAPACK DGELS: QR factorisation of A, then R x = Q^T b).
    !!
    !! a    [in]  real(dp)(m,n): the matrix, m >= n >= 1 (not changed: a copy is factored).
    !! b    [in]  real(dp)(m):   right-hand side.
    !! x    [out] real(dp)(n):   the solution.
    !! stat [out]: ERR_NUMERIC on a shape mismatch (m < n, sizes of b or x) or when R has an
    !!             exactly zero diagonal element (INFO = i > 0: A is not of full rank).
    subroutine la_lstsq(a, b, x, stat)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(in) :: b(:)
        real(dp), intent(out) :: x(:)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: ac(:, :), bc(:, :), work(:)
        real(dp) :: wquery(1)
        integer :: m, n, info, lwork
        character(len=100) :: buf
        m = size(a, 1)
        n = size(a, 2)
        x = 0.0_dp
        if (n < 1 .or. m < n .or. size(b) /= m .or. size(x) /= n) then
            call set_error(stat, ERR_NUMERIC, 'la_lstsq: shapes disagree (need m >= n >= 1, '// &
                           'size(b) = m, size(x) = n)')
            return
        end if
        allocate (ac(m, n), bc(m, 1))
        ac(:, :) = a
        bc(:, 1) = b
        call dgels('N', m, n, 1, ac, m, bc, m, wquery, -1, info)
        lwork = max(1, int(wquery(1)))
        allocate (work(lwork))
        call dgels('N', m, n, 1, ac, m, bc, m, work, lwork, info)
        if (info /= 0) then
            write (buf, '(a,i0,a,i0,a)') 'la_lstsq (dgels): the matrix is not of full rank (R(', &
                info, ',', info, ') = 0)'
            if (info < 0) write (buf, '(a,i0)') 'la_lstsq (dgels): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
            return
        end if
        x = bc(1:n, 1)
    end subroutine la_lstsq

    !> Singular values and right singular vectors of an m x n matrix, A = U S V^T (LAPACK
    !! DGESVD, U not formed).
    !!
    !! a    [in]  real(dp)(m,n): the matrix (not changed: a copy is reduced).
    !! s    [out] real(dp)(min(m,n)): singular values, decreasing.
    !! vt   [out] real(dp)(n,n): V^T, row i the right singular vector of s(i).
    !! stat [out]: ERR_NUMERIC on a shape mismatch or when the QR iteration of the
    !!             bidiagonal form does not converge (INFO > 0).
    subroutine la_svd(a, s, vt, stat)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(out) :: s(:)
        real(dp), intent(out) :: vt(:, :)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: ac(:, :), work(:)
        real(dp) :: u(1, 1), wquery(1)
        integer :: m, n, info, lwork
        character(len=100) :: buf
        m = size(a, 1)
        n = size(a, 2)
        s = 0.0_dp
        vt = 0.0_dp
        if (n < 1 .or. m < 1 .or. size(s) /= min(m, n) .or. any(shape(vt) /= [n, n])) then
            call set_error(stat, ERR_NUMERIC, 'la_svd: shapes disagree (size(s) = min(m, n), '// &
                           'vt n x n)')
            return
        end if
        allocate (ac(m, n))
        ac(:, :) = a
        call dgesvd('N', 'A', m, n, ac, m, s, u, 1, vt, n, wquery, -1, info)
        lwork = max(1, int(wquery(1)))
        allocate (work(lwork))
        call dgesvd('N', 'A', m, n, ac, m, s, u, 1, vt, n, work, lwork, info)
        if (info /= 0) then
            write (buf, '(a,i0,a)') 'la_svd (dgesvd): ', info, ' superdiagonals did not '// &
                'converge to zero'
            if (info < 0) write (buf, '(a,i0)') 'la_svd (dgesvd): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_svd

    !> Eigenvalues and eigenvectors of a real symmetric matrix (LAPACK DSYEV, lower
    !! triangle read).
    !!
    !! a    [in]  real(dp)(n,n): the symmetric matrix (not changed: a copy is reduced).
    !! w    [out] real(dp)(n):   eigenvalues in ascending order.
    !! v    [out] real(dp)(n,n): column j the unit eigenvector of w(j) (orthonormal).
    !! stat [out]: ERR_NUMERIC on a shape mismatch or when the QL/QR iteration fails to
    !!             converge (INFO = i > 0: i off-diagonal elements did not converge to zero).
    subroutine la_syev(a, w, v, stat)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(out) :: w(:)
        real(dp), intent(out) :: v(:, :)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: work(:)
        real(dp) :: wquery(1)
        integer :: n, info, lwork
        character(len=100) :: buf
        n = size(a, 1)
        w = 0.0_dp
        v = 0.0_dp
        if (n < 1 .or. size(a, 2) /= n .or. size(w) /= n .or. any(shape(v) /= [n, n])) then
            call set_error(stat, ERR_NUMERIC, 'la_syev: shapes disagree (a and v n x n, w n)')
            return
        end if
        v(:, :) = a
        call dsyev('V', 'L', n, v, n, w, wquery, -1, info)
        lwork = max(3*n, int(wquery(1)))
        allocate (work(lwork))
        call dsyev('V', 'L', n, v, n, w, work, lwork, info)
        if (info /= 0) then
            write (buf, '(a,i0,a)') 'la_syev (dsyev): ', info, ' off-diagonal elements did '// &
                'not converge to zero'
            if (info < 0) write (buf, '(a,i0)') 'la_syev (dsyev): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_syev

    !> Eigenvalues and right eigenvectors of a general real square matrix (LAPACK DGEEV).
    !!
    !! a    [in]  real(dp)(n,n): the matrix (not changed: a copy is reduced).
    !! wr, wi [out] real(dp)(n): real and imaginary parts of the eigenvalues; a conjugate
    !!            pair is adjacent, positive imaginary part first.
    !! vr   [out] real(dp)(n,n): right eigenvectors, each of unit Euclidean norm with its
    !!            largest component real: for a real eigenvalue column j is its vector; for
    !!            a pair j, j+1 the vector of wr(j) + i wi(j) is vr(:,j) + i vr(:,j+1).
    !! stat [out]: ERR_NUMERIC on a shape mismatch or when the QR algorithm fails to
    !!             converge (INFO > 0).
    subroutine la_eigv(a, wr, wi, vr, stat)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(out) :: wr(:), wi(:)
        real(dp), intent(out) :: vr(:, :)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: acopy(:, :), work(:)
        real(dp) :: vl(1, 1), wquery(1)
        integer :: n, info, lwork
        character(len=80) :: buf
        n = size(a, 1)
        wr = 0.0_dp
        wi = 0.0_dp
        vr = 0.0_dp
        if (n < 1 .or. size(a, 2) /= n .or. size(wr) /= n .or. size(wi) /= n .or. &
            any(shape(vr) /= [n, n])) then
            call set_error(stat, ERR_NUMERIC, 'la_eigv: shapes disagree (a and vr n x n, '// &
                           'wr and wi n)')
            return
        end if
        allocate (acopy(n, n))
        acopy(:, :) = a
        call dgeev('N', 'V', n, acopy, n, wr, wi, vl, 1, vr, n, wquery, -1, info)
        lwork = max(4*n, int(wquery(1)))
        allocate (work(lwork))
        call dgeev('N', 'V', n, acopy, n, wr, wi, vl, 1, vr, n, work, lwork, info)
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_eigv (dgeev): QR algorithm failed to converge, info = ', &
                info
            if (info < 0) write (buf, '(a,i0)') 'la_eigv (dgeev): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_eigv

    !> Cholesky factor of a symmetric positive definite matrix, A = L L^T (LAPACK DPOTRF,
    !! lower triangle).
    !!
    !! a    [in,out] real(dp)(n,n): the matrix (its lower triangle read); on return L in the
    !!               lower triangle and zeros above it.
    !! stat [out]: ERR_NUMERIC on a shape mismatch or when A is not positive definite
    !!             (INFO = i > 0: the leading minor of order i is not positive).
    subroutine la_chol(a, stat)
        real(dp), intent(inout) :: a(:, :)
        type(status_t), intent(out) :: stat
        integer :: n, info, j
        character(len=100) :: buf
        n = size(a, 1)
        if (n < 1 .or. size(a, 2) /= n) then
            call set_error(stat, ERR_NUMERIC, 'la_chol: the matrix is not square')
            return
        end if
        call dpotrf('L', n, a, n, info)
        if (info /= 0) then
            write (buf, '(a,i0,a)') 'la_chol (dpotrf): the leading minor of order ', info, &
                ' is not positive (the matrix is not positive definite)'
            if (info < 0) write (buf, '(a,i0)') 'la_chol (dpotrf): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
            return
        end if
        do j = 2, n
            a(1:j - 1, j) = 0.0_dp
        end do
    end subroutine la_chol

    !> Solve L X = B (or L^T X = B) in place for a lower triangular L (LAPACK DTRTRS), e.g.
    !! to whiten a least-squares problem by the Cholesky factor of its covariance.
    !!
    !! l    [in]     real(dp)(n,n): lower triangular, nonzero diagonal (la_chol's factor).
    !! b    [in,out] real(dp)(n,nrhs): right-hand sides; the solutions on return.
    !! stat [out]: ERR_NUMERIC on a shape mismatch or a zero diagonal element (INFO > 0).
    !! transposed [in, optional]: .true.: solve L^T X = B.
    subroutine la_tri_solve(l, b, stat, transposed)
        real(dp), intent(in) :: l(:, :)
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: stat
        logical, intent(in), optional :: transposed
        integer :: n, info
        character(len=1) :: tr
        character(len=80) :: buf
        n = size(l, 1)
        if (n < 1 .or. size(l, 2) /= n .or. size(b, 1) /= n) then
            call set_error(stat, ERR_NUMERIC, 'la_tri_solve: shapes disagree (l n x n, b n rows)')
            return
        end if
        if (size(b, 2) == 0) then
            stat%code = 0
            return
        end if
        tr = 'N'
        if (present(transposed)) then
            if (transposed) tr = 'T'
        end if
        call dtrtrs('L', tr, 'N', n, size(b, 2), l, n, b, n, info)
        if (info /= 0) then
            write (buf, '(a,i0,a)') 'la_tri_solve (dtrtrs): diagonal element ', info, ' is zero'
            if (info < 0) write (buf, '(a,i0)') 'la_tri_solve (dtrtrs): illegal argument ', -info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_tri_solve

end module lapack_wrap

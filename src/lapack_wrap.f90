!> Checked wrappers around the few LAPACK routines bifilar uses, and a written-out LU for
!! the smallest systems.
!!
!! Each wrapper checks the shapes of its arguments, calls LAPACK through an explicit
!! interface, and maps INFO to a status_t with a message naming the routine and the cause.
!! No wrapper stops the program.
!!
!! Systems of order n <= SMALL_N (the 5 x 5 system of eq. (38), solved at every right-hand
!! side) are factored by la_small_factor / la_small_solve: LAPACK's own unblocked algorithm
!! (DGETF2: partial pivoting on the first largest |a_ij| of the column, the column below
!! the pivot scaled by the pivot's reciprocal, rank-1 update; DGETRS: row interchanges,
!! unit lower then upper triangular solve by columns) written out, with the same operations
!! in the same order, so it gives LAPACK's results, without the call overhead (several
!! calls into reference BLAS, a heap-allocated pivot array) that costs more than the
!! arithmetic at n = 5.  Larger systems go to LAPACK.
module lapack_wrap
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    implicit none
    private

    public :: la_solve, la_lu_factor, la_lu_solve, la_lu_solve_many, la_eig, la_geig
    public :: la_small_factor, la_small_solve

    integer, parameter, public :: SMALL_N = 8   !! largest order la_solve factors itself

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
    end interface

contains

    !> Solve the small square system A x = b in place: LU with partial pivoting, for
    !! n <= SMALL_N written out (la_small_factor, la_small_solve), else by LAPACK's unblocked
    !! DGETF2 (for n of a few, the blocked recursive DGETRF/DGESV costs several times more),
    !! then DGETRS.
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
        if (n <= SMALL_N) then
            call la_small_factor(n, a, ipiv, stat)
            if (stat%code == 0) call la_small_solve(n, a, ipiv, b)
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

    !> LU factorisation with partial pivoting of a small square matrix (n <= SMALL_N; no
    !! shape checks beyond that: the caller owns the shapes), DGETF2's algorithm written out
    !! (see the module header): P A = L U, L unit lower triangular, stored like LAPACK's.
    !! Explicit shapes, so that a constant n lets the compiler unroll it.
    !!
    !! n    [in]     integer:       order, 1 <= n <= SMALL_N.
    !! a    [in,out] real(dp)(n,n): the matrix; overwritten by L (below the diagonal) and U.
    !! ipiv [out]    integer(n):    row i was interchanged with row ipiv(i).
    !! stat [out]: ERR_NUMERIC when U(j,j) is exactly zero (A singular; as DGETF2's INFO = j
    !!             the factorisation is completed) or n is out of range.
    pure subroutine la_small_factor(n, a, ipiv, stat)
        integer, intent(in) :: n
        real(dp), intent(inout) :: a(n, n)
        integer, intent(out) :: ipiv(n)
        type(status_t), intent(out) :: stat
        real(dp), parameter :: SFMIN = tiny(1.0_dp)
        real(dp) :: amax, t, r
        integer :: i, j, k, jp, info
        character(len=80) :: buf
        if (n > SMALL_N .or. n < 1) then
            ipiv = 0
            call set_error(stat, ERR_NUMERIC, 'la_small_factor: order n out of 1 ... SMALL_N')
            return
        end if
        info = 0
        do j = 1, n
            ! pivot: the first largest |a(i,j)|, i >= j (IDAMAX)
            jp = j
            amax = abs(a(j, j))
            do i = j + 1, n
                if (abs(a(i, j)) > amax) then
                    jp = i
                    amax = abs(a(i, j))
                end if
            end do
            ipiv(j) = jp
            if (a(jp, j) /= 0.0_dp) then
                if (jp /= j) then
                    do k = 1, n
                        t = a(j, k)
                        a(j, k) = a(jp, k)
                        a(jp, k) = t
                    end do
                end if
                if (abs(a(j, j)) >= SFMIN) then
                    r = 1.0_dp/a(j, j)
                    do i = j + 1, n
                        a(i, j) = r*a(i, j)
                    end do
                else
                    do i = j + 1, n
                        a(i, j) = a(i, j)/a(j, j)
                    end do
                end if
            else if (info == 0) then
                info = j
            end if
            ! rank-1 update of the trailing matrix (DGER with alpha = -1)
            do k = j + 1, n
                t = -a(j, k)
                do i = j + 1, n
                    a(i, k) = a(i, k) + a(i, j)*t
                end do
            end do
        end do
        if (info /= 0) then
            write (buf, '(a,i0)') 'la_small_factor: singular matrix, U(i,i) = 0 at i = ', info
            call set_error(stat, ERR_NUMERIC, trim(buf))
        end if
    end subroutine la_small_factor

    !> Solve A x = b with the factors from la_small_factor, in place (DGETRS's algorithm).
    !!
    !! n    [in]     integer:       order.
    !! lu   [in]     real(dp)(n,n): factors from la_small_factor (non-singular).
    !! ipiv [in]     integer(n):    its pivots.
    !! b    [in,out] real(dp)(n):   right-hand side on entry, solution on return.
    pure subroutine la_small_solve(n, lu, ipiv, b)
        integer, intent(in) :: n
        real(dp), intent(in) :: lu(n, n)
        integer, intent(in) :: ipiv(n)
        real(dp), intent(inout) :: b(n)
        real(dp) :: t
        integer :: i, k
        do i = 1, n
            if (ipiv(i) /= i) then
                t = b(i)
                b(i) = b(ipiv(i))
                b(ipiv(i)) = t
            end if
        end do
        do k = 1, n
            t = b(k)
            do i = k + 1, n
                b(i) = b(i) - t*lu(i, k)
            end do
        end do
        do k = n, 1, -1
            b(k) = b(k)/lu(k, k)
            t = b(k)
            do i = 1, k - 1
                b(i) = b(i) - t*lu(i, k)
            end do
        end do
    end subroutine la_small_solve

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

end module lapack_wrap

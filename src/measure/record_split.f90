!> A record of several releases cut into one record per release (&measurement
!! record_split = .true.): the body swung, was stopped by hand, held still (perhaps twisted
!! the other way) and released again, all in one file.  Each stop is a hold: a stretch at
!! least one swing period long where the record stands still within its noise.  A segment
!! runs from the start of a hold (or from the record's first sample when it starts
!! mid-swing) to one swing period before the next hold begins (the hand that stops and
!! twists the body is no part of the model); a hold that ends the record releases nothing.
!! Each segment is then an ordinary record: the record fit finds its release in it
!! (record_fit's find_release) and the releases are pooled as a table's are.
!!
!! The noise: the spread of the quiet windows (windows of an eighth of a period, the scaled
!! median absolute deviation of each about its median; the median of those within 3 times
!! the value a tenth of the windows lie below); a
!! window is still when its values stay within 8 times that noise of its median, or within
!! a thousandth of the record's whole range when that is larger.
module record_split
    use kinds, only: dp
    use records, only: record_t, median_value
    implicit none
    private

    public :: release_spans, segment_of, span_text

contains

    !> The segments of a record (samples lo(j) .. hi(j), in the order of time), cut at its
    !! holds as the module header says.  tp: the swing's period (s, > 0).  n_holds: the
    !! holds found (a record of one release: 0, or 1 when it starts held).  A segment is
    !! kept even when short: the caller refuses or skips it, naming its time span.
    subroutine release_spans(rec, tp, lo, hi, n_holds)
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: tp
        integer, allocatable, intent(out) :: lo(:), hi(:)
        integer, intent(out) :: n_holds
        real(dp) :: dt, noise, thr, med
        real(dp), allocatable :: mad(:)
        logical, allocatable :: still(:)
        integer :: n, w, nw, j, i0, i1, k, run0, guard, hs(size(rec%v)), he(size(rec%v))
        integer :: nh, s
        n = size(rec%v)
        allocate (lo(0), hi(0))
        n_holds = 0
        if (n < 2) then
            lo = [1]
            hi = [n]
            return
        end if
        dt = (rec%t(n) - rec%t(1))/(n - 1)
        w = max(5, nint(0.125_dp*tp/dt))
        nw = n/w
        if (nw < 2 .or. .not. (tp > 0.0_dp)) then
            lo = [1]
            hi = [n]
            return
        end if
        allocate (mad(nw), still(nw))
        do j = 1, nw
            i0 = (j - 1)*w + 1
            i1 = j*w
            med = median_value(rec%v(i0:i1))
            mad(j) = 1.4826_dp*median_value(abs(rec%v(i0:i1) - med))
        end do
        ! the quiet windows' spread: the median of those within 3 times the lowest tenth
        noise = lowest_decile(mad)
        noise = median_value(pack(mad, mad <= 3.0_dp*noise))
        thr = max(8.0_dp*noise, 1.0e-3_dp*(maxval(rec%v) - minval(rec%v)))
        do j = 1, nw
            i0 = (j - 1)*w + 1
            i1 = j*w
            med = median_value(rec%v(i0:i1))
            still(j) = maxval(abs(rec%v(i0:i1) - med)) <= thr
        end do
        ! holds: runs of still windows at least one period long (nh of them, samples)
        nh = 0
        run0 = 0
        do j = 1, nw + 1
            if (j <= nw) then
                if (still(j)) then
                    if (run0 == 0) run0 = j
                    cycle
                end if
            end if
            if (run0 > 0) then
                if ((j - run0)*w*dt >= tp) then
                    nh = nh + 1
                    hs(nh) = (run0 - 1)*w + 1
                    he(nh) = (j - 1)*w
                    if (j > nw) he(nh) = n
                end if
                run0 = 0
            end if
        end do
        ! a hold that ends the record releases nothing
        if (nh > 0) then
            if (he(nh) >= n - w) nh = nh - 1
        end if
        n_holds = nh
        guard = max(1, nint(tp/dt))
        ! the first segment: from the first sample when the record starts mid-swing
        s = 1
        if (nh > 0) then
            if (hs(1) <= w + 1) s = 0
        end if
        if (s == 1) then
            k = n
            if (nh > 0) k = max(1, hs(1) - guard)
            lo = [1]
            hi = [k]
        end if
        do j = 1, nh
            k = n
            if (j < nh) k = max(hs(j), hs(j + 1) - guard)
            lo = [lo, hs(j)]
            hi = [hi, k]
        end do
        if (size(lo) == 0) then
            lo = [1]
            hi = [n]
        end if
    contains
        !> The value a tenth of x lies below (at least the smallest).
        pure real(dp) function lowest_decile(x) result(v)
            real(dp), intent(in) :: x(:)
            real(dp) :: s(size(x)), a
            integer :: i, j2, m
            s = x
            ! insertion sort: a few hundred windows at most
            do i = 2, size(s)
                a = s(i)
                j2 = i - 1
                do while (j2 >= 1)
                    if (s(j2) <= a) exit
                    s(j2 + 1) = s(j2)
                    j2 = j2 - 1
                end do
                s(j2 + 1) = a
            end do
            m = max(1, size(s)/10)
            v = s(m)
        end function lowest_decile
    end subroutine release_spans

    !> The samples lo .. hi of a record as a record of their own (times as in the file), each
    !! block of its vs too (the three rates, or a track's two coordinates).
    pure function segment_of(rec, lo, hi) result(seg)
        type(record_t), intent(in) :: rec
        integer, intent(in) :: lo, hi
        type(record_t) :: seg
        integer :: n, m, k, nc
        n = size(rec%v)
        m = hi - lo + 1
        seg = rec
        seg%t = rec%t(lo:hi)
        seg%v = rec%v(lo:hi)
        if (allocated(rec%u)) then
            if (size(rec%u) == n) seg%u = rec%u(lo:hi)
        end if
        if (allocated(rec%vs) .and. n > 0) then
            ! blocks of n samples: three rates, or a track's two coordinates
            nc = size(rec%vs)/n
            if (nc*n == size(rec%vs)) then
                deallocate (seg%vs)
                allocate (seg%vs(nc*m))
                do k = 1, nc
                    seg%vs((k - 1)*m + 1:k*m) = rec%vs((k - 1)*n + lo:(k - 1)*n + hi)
                end do
            end if
        end if
    end function segment_of

    !> A segment's time span as text: "t = A s to B s".
    function span_text(rec, lo, hi) result(s)
        type(record_t), intent(in) :: rec
        integer, intent(in) :: lo, hi
        character(len=:), allocatable :: s
        character(len=32) :: a, b
        write (a, '(f0.3)') rec%t(lo)
        write (b, '(f0.3)') rec%t(hi)
        if (a(1:1) == '.') a = '0'//trim(a)
        if (b(1:1) == '.') b = '0'//trim(b)
        s = 't = '//trim(a)//' s to '//trim(b)//' s'
    end function span_text

end module record_split

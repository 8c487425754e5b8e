!> Figures as SVG text, for pages that must need no other file and run no script (the
!! certificate of a measurement): x-y plots of one or more series, drawn as lines or as
!! points with optional error bars, with axes, ticks at round numbers, a title and a legend.
!!
!! The figure is built in memory (`svg_plot_t`, `svg_add`) and rendered to one string
!! (`svg_render`) that can go straight into an HTML page.  Values that are not finite are
!! left out (a line breaks there); an axis whose values all coincide is widened so the
!! figure still has a scale.  A series of more than MAX_POINTS points is thinned for the
!! drawing to the smallest and largest value of each of BINS bins of x, which keeps
!! the envelope a reader sees.  No routine stops.
module svg_plot
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    use kinds, only: dp
    use text, only: itoa
    implicit none
    private

    !> One series of a figure.
    type, public :: svg_series_t
        real(dp), allocatable :: x(:), y(:)     !! the points
        real(dp), allocatable :: err(:)         !! error bars (+- err(i) in y), or none
        logical :: points = .false.             !! points (else a line)
        character(len=16) :: color = '#1f5fa8'  !! any SVG colour
        character(len=:), allocatable :: label  !! its legend entry ('' for none)
    end type svg_series_t

    !> A figure: its size in px, title, axis labels and series.
    type, public :: svg_plot_t
        integer :: width = 640, height = 340
        character(len=:), allocatable :: title, xlabel, ylabel
        type(svg_series_t), allocatable :: series(:)
    end type svg_plot_t

    public :: svg_new, svg_add, svg_render, nice_ticks, tick_text, xml_escaped

    !> Most points drawn of one series (more are thinned, see the header).
    integer, parameter :: MAX_POINTS = 2000
    !> Bins of a thinned series (each gives its smallest and largest value, and a break).
    integer, parameter :: BINS = 666
    !> Margins of the plotting area (px): left, right, top, bottom.
    integer, parameter :: ML = 72, MR = 16, MT = 30, MB = 44
    !> The widest coordinate px writes (characters).
    integer, parameter :: PX_LEN = 12

contains

    !> A figure with no series yet.
    pure function svg_new(title, xlabel, ylabel, width, height) result(p)
        character(len=*), intent(in) :: title, xlabel, ylabel
        integer, intent(in), optional :: width, height   !! px (default 640 x 340)
        type(svg_plot_t) :: p
        p%title = title
        p%xlabel = xlabel
        p%ylabel = ylabel
        if (present(width)) p%width = max(200, width)
        if (present(height)) p%height = max(120, height)
        allocate (p%series(0))
    end function svg_new

    !> Add a series (x and y of one size; err, when given, of the same size).
    pure subroutine svg_add(p, x, y, label, color, points, err)
        type(svg_plot_t), intent(inout) :: p
        real(dp), intent(in) :: x(:), y(:)
        character(len=*), intent(in) :: label
        character(len=*), intent(in), optional :: color
        logical, intent(in), optional :: points
        real(dp), intent(in), optional :: err(:)
        type(svg_series_t), allocatable :: grown(:)
        type(svg_series_t) :: s
        integer :: n, k
        n = min(size(x), size(y))
        s%x = x(1:n)
        s%y = y(1:n)
        if (present(err)) then
            if (size(err) >= n) s%err = err(1:n)
        end if
        s%label = label
        if (present(color)) s%color = color
        if (present(points)) s%points = points
        allocate (grown(size(p%series) + 1))
        do k = 1, size(p%series)
            grown(k) = p%series(k)
        end do
        grown(size(grown)) = s
        call move_alloc(grown, p%series)
    end subroutine svg_add

    !> The figure as one <svg> element.
    function svg_render(p) result(s)
        type(svg_plot_t), intent(in) :: p
        character(len=:), allocatable :: s
        real(dp) :: xlo, xhi, ylo, yhi, pw, ph
        real(dp), allocatable :: xt(:), yt(:)
        integer :: k, j, ly, np
        character(len=:), allocatable :: path
        logical :: pen
        real(dp), allocatable :: xs(:), ys(:), es(:)
        path = ''
        call data_range(p, .true., xlo, xhi)
        call data_range(p, .false., ylo, yhi)
        xt = nice_ticks(xlo, xhi)
        yt = nice_ticks(ylo, yhi)
        xlo = min(xlo, xt(1))
        xhi = max(xhi, xt(size(xt)))
        ylo = min(ylo, yt(1))
        yhi = max(yhi, yt(size(yt)))
        pw = real(p%width - ML - MR, dp)
        ph = real(p%height - MT - MB, dp)
        s = '<svg xmlns="http://www.w3.org/2000/svg" width="'//itoa(p%width)// &
            '" height="'//itoa(p%height)//'" viewBox="0 0 '//itoa(p%width)//' '// &
            itoa(p%height)//'" font-family="Helvetica, Arial, sans-serif" font-size="11">'
        s = s//'<rect x="'//itoa(ML)//'" y="'//itoa(MT)//'" width="'//px(pw)// &
            '" height="'//px(ph)//'" fill="white" stroke="#444"/>'
        ! ticks and grid
        do k = 1, size(xt)
            if (xt(k) < xlo .or. xt(k) > xhi) cycle
            s = s//'<line x1="'//px(sx(xt(k)))//'" y1="'//itoa(MT)//'" x2="'//px(sx(xt(k)))// &
                '" y2="'//itoa(p%height - MB)//'" stroke="#ddd"/>'
            s = s//'<text x="'//px(sx(xt(k)))//'" y="'//itoa(p%height - MB + 14)// &
                '" text-anchor="middle">'//tick_text(xt(k), xt)//'</text>'
        end do
        do k = 1, size(yt)
            if (yt(k) < ylo .or. yt(k) > yhi) cycle
            s = s//'<line x1="'//itoa(ML)//'" y1="'//px(sy(yt(k)))//'" x2="'// &
                itoa(p%width - MR)//'" y2="'//px(sy(yt(k)))//'" stroke="#ddd"/>'
            s = s//'<text x="'//itoa(ML - 4)//'" y="'//px(sy(yt(k)) + 4.0_dp)// &
                '" text-anchor="end">'//tick_text(yt(k), yt)//'</text>'
        end do
        s = s//'<text x="'//px(ML + pw/2)//'" y="'//itoa(p%height - 8)// &
            '" text-anchor="middle">'//xml_escaped(p%xlabel)//'</text>'
        s = s//'<text x="14" y="'//px(MT + ph/2)//'" text-anchor="middle" transform='// &
            '"rotate(-90 14 '//px(MT + ph/2)//')">'//xml_escaped(p%ylabel)//'</text>'
        s = s//'<text x="'//px(ML + pw/2)//'" y="18" text-anchor="middle" font-size="13" '// &
            'font-weight="bold">'//xml_escaped(p%title)//'</text>'
        ! the series
        ly = MT + 14
        do k = 1, size(p%series)
            call thinned(p%series(k), xs, ys, es)
            if (p%series(k)%points) then
                do j = 1, size(xs)
                    if (.not. (ieee_is_finite(xs(j)) .and. ieee_is_finite(ys(j)))) cycle
                    if (size(es) > 0) then
                        if (ieee_is_finite(es(j)) .and. es(j) > 0.0_dp) s = s// &
                            '<line x1="'//px(sx(xs(j)))//'" y1="'//px(sy(ys(j) - es(j)))// &
                            '" x2="'//px(sx(xs(j)))//'" y2="'//px(sy(ys(j) + es(j)))// &
                            '" stroke="'//trim(p%series(k)%color)//'"/>'
                    end if
                    s = s//'<circle cx="'//px(sx(xs(j)))//'" cy="'//px(sy(ys(j)))// &
                        '" r="2.5" fill="'//trim(p%series(k)%color)//'"/>'
                end do
            else
                ! the path's text in a buffer of its largest size (no copy per point)
                deallocate (path)
                allocate (character(len=size(xs)*(2*PX_LEN + 3)) :: path)
                np = 0
                pen = .false.
                do j = 1, size(xs)
                    if (.not. (ieee_is_finite(xs(j)) .and. ieee_is_finite(ys(j)))) then
                        pen = .false.
                        cycle
                    end if
                    call put(merge('L', 'M', pen)//px(sx(xs(j)))//' '//px(sy(ys(j)))//' ')
                    pen = .true.
                end do
                if (np > 0) s = s//'<path d="'//path(1:np)//'" fill="none" stroke="'// &
                    trim(p%series(k)%color)//'" stroke-width="1.2"/>'
            end if
            if (len(p%series(k)%label) > 0) then
                s = s//'<line x1="'//itoa(p%width - MR - 150)//'" y1="'//itoa(ly - 4)// &
                    '" x2="'//itoa(p%width - MR - 132)//'" y2="'//itoa(ly - 4)// &
                    '" stroke="'//trim(p%series(k)%color)//'" stroke-width="2"/>'
                s = s//'<text x="'//itoa(p%width - MR - 128)//'" y="'//itoa(ly)//'">'// &
                    xml_escaped(p%series(k)%label)//'</text>'
                ly = ly + 14
            end if
        end do
        s = s//'</svg>'

    contains

        real(dp) function sx(x)
            real(dp), intent(in) :: x
            sx = ML + pw*(x - xlo)/(xhi - xlo)
        end function sx

        real(dp) function sy(y)
            real(dp), intent(in) :: y
            sy = MT + ph*(1.0_dp - (min(max(y, ylo - (yhi - ylo)), yhi + (yhi - ylo)) - ylo)/ &
                                   (yhi - ylo))
        end function sy

        !> Append t to the path's buffer (px writes at most PX_LEN characters).
        subroutine put(t)
            character(len=*), intent(in) :: t
            path(np + 1:np + len(t)) = t
            np = np + len(t)
        end subroutine put
    end function svg_render

    !> The range of x (or y, with its error bars) over every finite point, widened when empty
    !! or a single value.
    subroutine data_range(p, along_x, lo, hi)
        type(svg_plot_t), intent(in) :: p
        logical, intent(in) :: along_x
        real(dp), intent(out) :: lo, hi
        integer :: k, j
        real(dp) :: v, e
        lo = huge(1.0_dp)
        hi = -huge(1.0_dp)
        do k = 1, size(p%series)
            do j = 1, size(p%series(k)%x)
                if (.not. (ieee_is_finite(p%series(k)%x(j)) .and. &
                           ieee_is_finite(p%series(k)%y(j)))) cycle
                e = 0.0_dp
                if (along_x) then
                    v = p%series(k)%x(j)
                else
                    v = p%series(k)%y(j)
                    if (allocated(p%series(k)%err)) then
                        if (ieee_is_finite(p%series(k)%err(j))) e = abs(p%series(k)%err(j))
                    end if
                end if
                lo = min(lo, v - e)
                hi = max(hi, v + e)
            end do
        end do
        if (lo > hi) then
            lo = 0.0_dp
            hi = 1.0_dp
        else if (.not. (hi - lo > 1.0e-12_dp*max(abs(lo), abs(hi)))) then
            v = max(abs(lo)*1.0e-3_dp, 1.0e-300_dp)
            if (lo == 0.0_dp) v = 1.0_dp
            lo = lo - v
            hi = hi + v
        end if
    end subroutine data_range

    !> Round tick values covering lo .. hi: steps of 1, 2 or 5 times a power of ten, 4 to 10
    !! ticks.
    pure function nice_ticks(lo, hi) result(t)
        real(dp), intent(in) :: lo, hi
        real(dp), allocatable :: t(:)
        real(dp) :: span, step, base, f
        integer :: k, k0, k1
        span = hi - lo
        if (.not. (span > 0.0_dp)) span = max(abs(lo), 1.0_dp)
        base = 10.0_dp**floor(log10(span/5.0_dp))
        f = span/(5.0_dp*base)
        if (f < 1.5_dp) then
            step = base
        else if (f < 3.5_dp) then
            step = 2.0_dp*base
        else if (f < 7.5_dp) then
            step = 5.0_dp*base
        else
            step = 10.0_dp*base
        end if
        k0 = floor(lo/step + 1.0e-9_dp)
        k1 = ceiling(hi/step - 1.0e-9_dp)
        allocate (t(k1 - k0 + 1))
        do k = k0, k1
            t(k - k0 + 1) = k*step
        end do
    end function nice_ticks

    !> A tick value as text with as many decimals as the ticks' step needs (E format for
    !! very large or small values).
    function tick_text(v, ticks) result(s)
        real(dp), intent(in) :: v, ticks(:)
        character(len=:), allocatable :: s
        character(len=40) :: buf
        real(dp) :: step, big
        integer :: nd
        step = 1.0_dp
        if (size(ticks) > 1) step = abs(ticks(2) - ticks(1))
        big = maxval(abs(ticks))
        if (abs(v) < 1.0e-9_dp*step) then
            s = '0'
            return
        end if
        if (big >= 1.0e5_dp .or. big < 1.0e-3_dp) then
            nd = max(0, min(6, floor(log10(big)) - floor(log10(step) + 1.0e-9_dp)))
            write (buf, '(es20.'//itoa(nd)//')') v
        else
            nd = max(0, -floor(log10(step) + 1.0e-9_dp))
            write (buf, '(f25.'//itoa(nd)//')') v
        end if
        s = trim(adjustl(buf))
        ! f25.0 writes '10.': a whole number is written without its point
        if (len(s) > 1) then
            if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
        end if
    end function tick_text

    !> The series as drawn: at most MAX_POINTS points (see the header).
    subroutine thinned(ser, xs, ys, es)
        type(svg_series_t), intent(in) :: ser
        real(dp), allocatable, intent(out) :: xs(:), ys(:), es(:)
        integer :: n, nb, b, j, ilo, ihi, m, jlo, jhi
        logical :: gap
        n = size(ser%x)
        if (n <= MAX_POINTS .or. ser%points) then
            xs = ser%x
            ys = ser%y
            if (allocated(ser%err)) then
                es = ser%err
            else
                allocate (es(0))
            end if
            return
        end if
        nb = BINS
        allocate (xs(3*nb), ys(3*nb), es(0))
        m = 0
        gap = .false.
        do b = 1, nb
            ilo = 1 + ((b - 1)*n)/nb
            ihi = (b*n)/nb
            if (ihi < ilo) cycle
            jlo = 0
            jhi = 0
            do j = ilo, ihi
                if (.not. (ieee_is_finite(ser%x(j)) .and. ieee_is_finite(ser%y(j)))) then
                    gap = .true.
                    cycle
                end if
                if (jlo == 0) then
                    jlo = j
                    jhi = j
                end if
                if (ser%y(j) < ser%y(jlo)) jlo = j
                if (ser%y(j) > ser%y(jhi)) jhi = j
            end do
            if (jlo == 0) cycle
            if (gap .and. m > 0) then
                ! a value left out: the line breaks here
                m = m + 1
                xs(m) = ieee_value(1.0_dp, ieee_quiet_nan)
                ys(m) = xs(m)
                gap = .false.
            end if
            m = m + 1
            xs(m) = ser%x(min(jlo, jhi))
            ys(m) = ser%y(min(jlo, jhi))
            m = m + 1
            xs(m) = ser%x(max(jlo, jhi))
            ys(m) = ser%y(max(jlo, jhi))
        end do
        xs = xs(1:m)
        ys = ys(1:m)
    end subroutine thinned

    !> A coordinate in px with one decimal.
    function px(v) result(s)
        real(dp), intent(in) :: v
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write (buf, '(f'//itoa(PX_LEN)//'.1)') v
        s = trim(adjustl(buf))
    end function px

    !> Text with &, <, > and " escaped for XML (an SVG's text, an HTML page's: the
    !! certificate's html_escaped).
    pure function xml_escaped(t) result(s)
        character(len=*), intent(in) :: t
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, len(t)
            select case (t(i:i))
            case ('&')
                s = s//'&amp;'
            case ('<')
                s = s//'&lt;'
            case ('>')
                s = s//'&gt;'
            case ('"')
                s = s//'&quot;'
            case default
                s = s//t(i:i)
            end select
        end do
    end function xml_escaped

end module svg_plot

!> Suite certificate: the figures as SVG (round ticks, every value drawn or left out when
!! not finite, thinning of long series) and the certificate page (escaping, balanced
!! elements, the fields it must hold, written whole through the run's files), an identify
!! run's page and a tensor run's page.
module test_certificate
    use kinds, only: dp
    use status, only: status_t
    use text, only: itoa
    use testing, only: tester_t, fresh_dir, exists, run, read_kv_text
    use svg_plot, only: svg_plot_t, svg_new, svg_add, svg_render, nice_ticks, tick_text
    use certificate, only: certificate_t, cert_new, cert_section, cert_text, cert_table, &
        cert_row, cert_figure, cert_html, cert_write, html_escaped, cert_note, CELL
    use output_io, only: out_files_t
    use unused_arg, only: unused
    implicit none
    private

    public :: run_certificate_tests, balanced, count_of

    character(len=*), parameter :: SCR = 'build/test_certificate'

contains

    subroutine run_certificate_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        if (t%want('certificate: round ticks, SVG figures')) call test_svg(t)
        if (t%want('certificate: the page')) call test_page(t)
        if (t%want('certificate: an identify run''s page holds every field')) &
            call test_identify_page(t, exe)
        if (t%want('certificate: a tensor run''s page holds every field')) &
            call test_tensor_page(t, exe)
    end subroutine run_certificate_tests

    subroutine test_svg(t)
        type(tester_t), intent(inout) :: t
        real(dp), allocatable :: tk(:), x(:), y(:)
        type(svg_plot_t) :: p
        character(len=:), allocatable :: s
        integer :: i
        logical :: ok
        allocate (tk(0))
        tk = nice_ticks(0.013_dp, 0.0871_dp)
        ok = size(tk) >= 4 .and. size(tk) <= 11 .and. tk(1) <= 0.013_dp .and. &
             tk(size(tk)) >= 0.0871_dp
        call t%check('certificate: ticks cover 0.013 .. 0.0871 with 4 to 11 round values ('// &
                     itoa(size(tk))//')', ok)
        call t%check('certificate: a tick of step 0.01 reads 0.05, not 0.05000000001', &
                     tick_text(5*0.01_dp, [0.0_dp, 0.01_dp]) == '0.05')
        call t%check('certificate: a whole tick is written without its point', &
                     tick_text(10.0_dp, [0.0_dp, 5.0_dp, 10.0_dp]) == '10')
        call t%check('certificate: a tick in E format for large values', &
                     index(tick_text(2.0e6_dp, [0.0_dp, 1.0e6_dp, 2.0e6_dp]), 'E') > 0)
        allocate (x(5000), y(5000))
        do i = 1, size(x)
            x(i) = 0.01_dp*i
            y(i) = sin(x(i))
        end do
        y(100) = ieee_nan()
        p = svg_new('A <test> & figure', 't (s)', 'rate (rad/s)')
        call svg_add(p, x, y, 'record')
        call svg_add(p, [1.0_dp, 2.0_dp], [0.5_dp, 0.7_dp], 'points', color='#c00', &
                     points=.true., err=[0.1_dp, 0.2_dp])
        s = svg_render(p)
        call t%check('certificate: one <svg> element, balanced', &
                     count_of(s, '<svg ') == 1 .and. count_of(s, '</svg>') == 1)
        call t%check('certificate: no NaN or Infinity drawn', &
                     index(s, 'NaN') == 0 .and. index(s, 'Infinity') == 0)
        call t%check('certificate: the title escaped', index(s, 'A &lt;test&gt; &amp; figure') > 0)
        call t%check('certificate: a line of 5000 points thinned to at most 2000, broken at '// &
                     'the NaN', count_of(s, 'L') <= 2000 .and. count_of(s, '<path d="M') == 1)
        call t%check('certificate: two points with error bars', count_of(s, '<circle') == 2)
    end subroutine test_svg

    subroutine test_page(t)
        type(tester_t), intent(inout) :: t
        type(certificate_t) :: c
        type(svg_plot_t) :: p
        type(out_files_t) :: files
        type(status_t) :: st
        character(len=:), allocatable :: s
        integer :: u, ios, n
        character(len=4096) :: line
        logical :: ok
        c = cert_new('Certificate of measurement', 'body "X" & rig', '1.1', 'in/x.nml', &
                     '0123456789abcdef')
        call cert_section(c, 'Result')
        call cert_text(c, 'I1 = 5.12E-02 kg m² ± 2.0E-04')
        call cert_table(c, 'input'//CELL//'value'//CELL//'u')
        call cert_row(c, 'mass'//CELL//'1.234'//CELL//'1.0E-03')
        call cert_note(c, 'a warning <that stands>')
        p = svg_new('f', 'x', 'y')
        call svg_add(p, [0.0_dp, 1.0_dp], [0.0_dp, 1.0_dp], '')
        call cert_figure(c, svg_render(p), 'the fit')
        s = cert_html(c, '2026-11-27 12:00:00')
        call t%check('certificate: escaped text', index(s, 'body &quot;X&quot; &amp; rig') > 0 &
                     .and. index(s, '&lt;that stands&gt;') > 0)
        call t%check('certificate: elements balanced', balanced(s))
        call t%check('certificate: numbers right-aligned', index(s, '<td class="n">1.234</td>') > 0)
        call t%check('certificate: A4, no script, the version, CRC-64 and date', &
                     index(s, 'size: A4') > 0 .and. index(s, '<script') == 0 .and. &
                     index(s, 'bifilar 1.1') > 0 .and. index(s, '0123456789abcdef') > 0 .and. &
                     index(s, '2026-11-27 12:00:00') > 0)
        call fresh_dir(SCR)
        call cert_write(c, SCR//'/x.certificate.html', '2026-11-27 12:00:00', files, st)
        if (st%code == 0) call files%commit(st)
        if (st%code /= 0) write (*, '(a)') '   '//st%msg
        ok = exists(SCR//'/x.certificate.html')
        call t%check('certificate: written whole through the run''s files', st%code == 0 .and. ok)
        n = 0
        open (newunit=u, file=SCR//'/x.certificate.html', status='old', action='read', &
              iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios == 0 .and. index(line, '</html>') > 0) n = n + 1
        end do
        close (u)
        call t%check('certificate: the file ends the page', n == 1)
    end subroutine test_page

    !> identify on the periods deck and on the record deck: each writes
    !! NAME.certificate.html beside NAME.identify, balanced, without a script, holding each
    !! section (result, body and rig, method, budget, checks, figures), I1 and U as in
    !! NAME.identify, every budget row, the figure, the version, the deck's CRC-64 and the date.
    subroutine test_identify_page(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: DECKS(2) = [character(len=16) :: 'identify_periods', &
                                                  'identify_record']
        character(len=:), allocatable :: page, path
        character(len=64) :: val
        character(len=*), parameter :: SECTIONS(6) = [character(len=28) :: '1. Result', &
            '2. Body and rig as measured', '3. Method and model', &
            '4. Uncertainty budget of I1', '5. Checks', '6. Figures']
        integer :: k, j, ex
        logical :: ok
        do k = 1, size(DECKS)
            call fresh_dir(SCR//'/id')
            ex = run(exe//' input/'//trim(DECKS(k))//'.nml --out '//SCR//'/id', SCR)
            path = SCR//'/id/'//trim(DECKS(k))//'.certificate.html'
            ok = exists(path)
            call t%check('certificate: '//trim(DECKS(k))//' ends 0 and writes its page', &
                         ex == 0 .and. ok)
            if (.not. ok) cycle
            page = whole(path)
            call t%check('certificate: '//trim(DECKS(k))//': balanced, no script', &
                         balanced(page) .and. index(page, '<script') == 0)
            ok = .true.
            do j = 1, size(SECTIONS)
                if (index(page, trim(SECTIONS(j))) == 0) then
                    ok = .false.
                    write (*, '(a)') '   no section '//trim(SECTIONS(j))
                end if
            end do
            call t%check('certificate: '//trim(DECKS(k))//': every section', ok)
            call read_kv_text(SCR//'/id/'//trim(DECKS(k))//'.identify', 'I1', val)
            call t%check('certificate: '//trim(DECKS(k))//': I1 as in the .identify file', &
                         len_trim(val) > 0 .and. index(page, 'I1 = '//trim(sci6(val))) > 0)
            call t%check('certificate: '//trim(DECKS(k))//': every budget row, the figure', &
                         index(page, '>b_prime<') > 0 .and. index(page, '>mass<') > 0 .and. &
                         index(page, '<svg') > 0 .and. index(page, 'share of u^2') > 0)
            call t%check('certificate: '//trim(DECKS(k))//': version, CRC-64 and date', &
                         index(page, 'bifilar 1.1') > 0 .and. index(page, 'CRC-64') > 0 .and. &
                         index(page, ' 20') > 0)
        end do
    contains
        !> 5.12077E-02 from 5.1207746E-02 (as the page rounds I1 to 6 digits)
        function sci6(v) result(s)
            character(len=*), intent(in) :: v
            character(len=:), allocatable :: s
            real(dp) :: x
            character(len=20) :: buf
            integer :: ios
            read (v, *, iostat=ios) x
            s = '?'
            if (ios /= 0) return
            write (buf, '(es11.5)') x
            s = trim(adjustl(buf))
        end function sci6
    end subroutine test_identify_page

    !> tensor on the shipped example (its Monte Carlo off): NAME.certificate.html beside
    !! NAME.tensor, balanced, without a script, holding each section (result, mass centre,
    !! body and rig, method, budget, checks, hangs, figure), the principal moments and their
    !! U as in NAME.tensor, the entries, the axes, the checks (positive definite, triangle,
    !! chi^2, the smallest angle between hangs), the budget's rows, every hang, the figure,
    !! the version, the deck's CRC-64 and the date.
    subroutine test_tensor_page(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: SECTIONS(8) = [character(len=28) :: '1. Result', &
            '2. Mass centre', '3. Body and rig as measured', '4. Method and model', &
            '5. Uncertainty budget', '6. Checks', '7. Hangs', '8. Figure']
        character(len=*), parameter :: FIELDS(14) = [character(len=48) :: '>J_xx<', '>J_yz<', &
            '>I_3<', 'U (95 %)', 'axis (x, y, z)', 'positive definite', 'triangle: I_3', &
            'fit: chi^2 (dof)', 'smallest angle between two hangs', '>b_prime<', &
            '>direction(1)<', 'vertical moment measured', 'model''s period', '<svg']
        character(len=:), allocatable :: page, path, dir
        character(len=256) :: val
        real(dp) :: m(3), big_u(3)
        integer :: j, ex, ios
        logical :: ok
        dir = SCR//'/tensor'
        call fresh_dir(dir)
        call execute_command_line('sed -e "s/monte_carlo = 2000/monte_carlo = 0/" '// &
            'input/tensor_example.nml > '//dir//'/tensor_example.nml && cp '// &
            'input/tensor_example_hangs.csv '//dir//'/')
        ex = run(exe//' '//dir//'/tensor_example.nml --out '//dir, SCR)
        path = dir//'/tensor_example.certificate.html'
        ok = exists(path)
        call t%check('certificate: tensor_example ends 0 and writes its page', ex == 0 .and. ok)
        if (.not. ok) return
        page = whole(path)
        call t%check('certificate: tensor_example: balanced, no script, A4', balanced(page) &
                     .and. index(page, '<script') == 0 .and. index(page, 'size: A4') > 0)
        ok = .true.
        do j = 1, size(SECTIONS)
            if (index(page, trim(SECTIONS(j))) == 0) then
                ok = .false.
                write (*, '(a)') '   no section '//trim(SECTIONS(j))
            end if
        end do
        call t%check('certificate: tensor_example: every section', ok)
        ok = .true.
        do j = 1, size(FIELDS)
            if (index(page, trim(FIELDS(j))) == 0) then
                ok = .false.
                write (*, '(a)') '   no field '//trim(FIELDS(j))
            end if
        end do
        call t%check('certificate: tensor_example: the entries, moments, axes, checks, '// &
                     'budget, hangs, figure', ok)
        call read_kv_text(dir//'/tensor_example.tensor', 'I_principal', val)
        read (val, *, iostat=ios) m
        call read_kv_text(dir//'/tensor_example.tensor', 'U95_I_principal', val)
        if (ios == 0) read (val, *, iostat=ios) big_u
        ok = ios == 0
        do j = 1, 3
            if (ok) ok = index(page, '>'//es(m(j), 12, 6)//'<') > 0 .and. &
                         index(page, '>'//es(big_u(j), 8, 2)//'<') > 0
        end do
        call t%check('certificate: tensor_example: the principal moments and their U as in '// &
                     'the .tensor file', ok)
        ok = .true.
        do j = 1, 9
            if (index(page, '<tr><td class="n">'//itoa(j)//'</td><td>') == 0) ok = .false.
        end do
        call t%check('certificate: tensor_example: each of the nine hangs', ok)
        call t%check('certificate: tensor_example: version, CRC-64 and date', &
                     index(page, 'bifilar 1.1') > 0 .and. index(page, 'CRC-64 of the deck') > 0 &
                     .and. index(page, ' 20') > 0)
    contains
        function es(x, w, d) result(s)
            real(dp), intent(in) :: x
            integer, intent(in) :: w, d
            character(len=:), allocatable :: s
            character(len=32) :: buf
            write (buf, '(es'//itoa(w)//'.'//itoa(d)//')') x
            s = trim(adjustl(buf))
        end function es
    end subroutine test_tensor_page

    !> A whole text file as one string, lines joined by new lines.
    function whole(path) result(s)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: s
        character(len=65536) :: line
        integer :: u, ios
        s = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios == 0) s = s//trim(line)//achar(10)
        end do
        if (ios > 0 .or. ios == -1) close (u)
    end function whole

    !> Each element that must be closed (html, body, table, tr, svg, figure, p, h1, h2) is
    !! opened as often as closed, and never closed before it is opened.
    logical function balanced(s)
        character(len=*), intent(in) :: s
        character(len=8), parameter :: TAGS(*) = [character(len=8) :: 'html', 'body', &
            'table', 'tr', 'svg', 'figure', 'h1', 'h2', 'footer', 'style', 'title']
        integer :: k, i, depth
        balanced = .true.
        do k = 1, size(TAGS)
            depth = 0
            do i = 1, len(s) - len_trim(TAGS(k)) - 1
                if (s(i:i) /= '<') cycle
                if (opens(s(i + 1:), trim(TAGS(k)))) depth = depth + 1
                if (s(i + 1:i + 1) == '/') then
                    if (opens(s(i + 2:), trim(TAGS(k)))) depth = depth - 1
                end if
                if (depth < 0) balanced = .false.
            end do
            if (depth /= 0) balanced = .false.
        end do
    contains
        logical function opens(rest, tag)
            character(len=*), intent(in) :: rest, tag
            opens = .false.
            if (len(rest) <= len(tag)) return
            opens = rest(1:len(tag)) == tag .and. index(' >', rest(len(tag) + 1:len(tag) + 1)) > 0
        end function opens
    end function balanced

    !> How often `w` occurs in s.
    integer function count_of(s, w) result(n)
        character(len=*), intent(in) :: s, w
        integer :: i, j
        n = 0
        i = 1
        do
            j = index(s(i:), w)
            if (j == 0) exit
            n = n + 1
            i = i + j + len(w) - 1
            if (i > len(s)) exit
        end do
    end function count_of

    real(dp) function ieee_nan()
        use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
        ieee_nan = ieee_value(1.0_dp, ieee_quiet_nan)
    end function ieee_nan

end module test_certificate

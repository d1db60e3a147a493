!> The flume's circle taken alone where its blend is the circle to the last
!> bit (geometry_cross_section's flume_circle_alone, issue 26's speed goal):
!> flume_evaluate against the blend of every term written out here (the
!> evaluation before the shortcut: both joints' logistic weights, the three
!> parts, Leibniz's sum in v), every partial of every order 0..3 bit for bit
!> at v across and beyond the range (a fine grid, random points, the doubles
!> beside pi/2 and the shortcut's borders), for flumes of several radii and
!> joint widths; the shortcut is taken over most of the circle (else it
!> saves nothing) and never near a joint, where the blend differs from the
!> circle. The partials against differences: test_cross_section.
program test_flume_circle_alone
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_cross_section, only: flume_section_t, section_point_t, logistic, logistic_rate, blend_weights, &
                                    flume_circle_alone
  use testing, only: check, finish_tests
  implicit none (type, external)

  integer, parameter :: binom(0:3, 0:3) = reshape([1, 0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1, 3, 3, 1], [4, 4])
  type(flume_section_t) :: flumes(6)
  integer :: f

  flumes(1) = flume_section_t()                                             ! the thesis's: 0.52 m, 0.164 m, 0.05 rad
  flumes(2) = flume_section_t(radius=0.6_wp, wall=0.5_wp)                   ! inputs/parts/funnel_slide.nml
  flumes(3) = flume_section_t(radius=2.4_wp, wall=1.0_wp, transition=0.1_wp)
  flumes(4) = flume_section_t(radius=0.3_wp, wall=0.1_wp, transition=0.01_wp)
  flumes(5) = flume_section_t(radius=1.0_wp, wall=0.5_wp, transition=1e-4_wp)
  flumes(6) = flume_section_t(radius=0.52_wp, wall=0.164_wp, transition=1.2_wp)   ! wide joints: no shortcut
  do f = 1, size(flumes)
    call check_flume(flumes(f), f)
  end do
  call finish_tests('flume circle alone')

contains

  !> Every partial of flume_evaluate at v, orders 0..3, against the whole
  !> blend bit for bit; `alone` counts where the shortcut holds.
  subroutine compare_at(flume, v, same, alone)
    type(flume_section_t), intent(in) :: flume
    real(wp), intent(in) :: v
    logical, intent(inout) :: same
    integer, intent(inout) :: alone
    type(section_point_t) :: p, q
    type(status_t) :: st
    integer :: order
    do order = 0, 3
      call flume%evaluate(0.0_wp, v, order, p, st)
      q = whole_blend(flume, v, order)
      if (.not. (st%ok() .and. p%order == q%order .and. all(p%s == q%s) .and. &
                 all(sign(1.0_wp, p%s) == sign(1.0_wp, q%s)))) then
        if (same) print '(a, es24.16, a, i0)', '  first difference at v = ', v, ', order ', order
        same = .false.
      end if
    end do
    if (flume_circle_alone(logistic_rate(0.0_wp, flume%transition), flume%radius, v, cos(v), sin(v))) &
      alone = alone + 1
  end subroutine compare_at

  subroutine check_flume(flume, which)
    type(flume_section_t), intent(in) :: flume
    integer, intent(in) :: which
    integer, parameter :: n_grid = 40000, n_random = 20000
    real(wp) :: v_min, v_max, v, xi, r, x(n_random), t_alone, t_blend, c(2, 0:3)
    type(section_point_t) :: q
    integer :: i, alone, on_circle, near
    logical :: same, was
    character(len=2) :: tag
    write (tag, '(i0)') which
    call flume%v_range(v_min, v_max)
    xi = logistic_rate(0.0_wp, flume%transition)
    r = flume%radius
    same = .true.
    alone = 0
    on_circle = 0
    do i = 0, n_grid
      v = v_min - 0.1_wp + (v_max - v_min + 0.2_wp)*i/n_grid
      call compare_at(flume, v, same, alone)
      if (v > 0 .and. v < pi) on_circle = on_circle + 1
    end do
    call random_seed(put=[(1234 + 17*i + which, i = 1, 64)])
    call random_number(x)
    do i = 1, n_random
      call compare_at(flume, v_min + (v_max - v_min)*x(i), same, alone)
    end do
    ! pi/2's doubles, where cos v is smallest (the circle's smallest partial)
    v = pi/2
    do i = 1, 50
      call compare_at(flume, v, same, alone)
      call compare_at(flume, nearest(pi/2, 1.0_wp)*(1 + i*epsilon(v)), same, alone)
      v = nearest(v, -1.0_wp)
    end do
    ! the shortcut's borders: every switch found on the grid, each side to
    ! the double (bisection)
    was = .false.
    t_alone = huge(1.0_wp)
    do i = 0, n_grid
      v = (pi*i)/n_grid
      if (flume_circle_alone(xi, r, v, cos(v), sin(v)) .neqv. was) then
        call border(flume, xi, r, pi*(i - 1)/n_grid, v, same, alone)
        was = .not. was
        if (was) t_alone = min(t_alone, xi*min(v, pi - v))
      end if
    end do
    call check(same, 'flume '//trim(tag)//': every partial of orders 0..3 the whole blend''s to the bit')
    ! near a joint the blend is not the circle: the shortcut is not taken
    ! there (t_blend: the nearest to the joint where the blend differs)
    t_blend = 0
    near = 0
    do i = 1, n_grid
      v = (pi/2*i)/n_grid
      q = whole_blend(flume, v, 3)
      c(:, 0) = [-r*cos(v), -r*sin(v)]; c(:, 1) = [r*sin(v), -r*cos(v)]
      c(:, 2) = [r*cos(v), r*sin(v)];   c(:, 3) = [-r*sin(v), r*cos(v)]
      if (any(q%s(:, 0, 0:3) /= c)) then
        t_blend = max(t_blend, xi*v)
        near = near + 1
        if (flume_circle_alone(xi, r, v, cos(v), sin(v))) then
          call check(.false., 'flume '//trim(tag)//': the shortcut taken where the blend is not the circle')
          exit
        end if
      end if
    end do
    if (which == 6) then   ! joints 1.2 rad wide: the blend nowhere the circle alone
      call check(alone == 0 .and. near == n_grid, 'flume 6 (wide joints): no shortcut, the blend everywhere')
    else
      call check(near > 0, 'flume '//trim(tag)//': the blend near its joint is not the circle (the test sees it)')
      ! the shortcut on most of the circle: its border within a few xi units
      ! of where the blend becomes the circle to the bit
      call check(t_alone < t_blend + 40, 'flume '//trim(tag)//': the shortcut from t = xi |v - joint| = '// &
                 fmt(t_alone)//', the blend the circle''s from t = '//fmt(t_blend))
      if (flume%transition <= 0.05_wp) then   ! the shipped joints' widths and narrower
        call check(real(alone, wp) > 0.3_wp*on_circle, 'flume '//trim(tag)//': the shortcut on more than 30 % '// &
                   'of the circle''s grid points')
      else
        call check(alone > 0, 'flume '//trim(tag)//': the shortcut taken at the bottom')
      end if
    end if
  end subroutine check_flume

  !> Between v = a (shortcut as at a) and b (the other): bisect to the two
  !> neighbouring doubles at the switch and compare both and a few beside.
  subroutine border(flume, xi, r, a, b, same, alone)
    type(flume_section_t), intent(in) :: flume
    real(wp), intent(in) :: xi, r, a, b
    logical, intent(inout) :: same
    integer, intent(inout) :: alone
    real(wp) :: lo, hi, mid
    logical :: at_lo
    integer :: k
    lo = a; hi = b
    at_lo = flume_circle_alone(xi, r, lo, cos(lo), sin(lo))
    do k = 1, 200
      mid = (lo + hi)/2
      if (mid <= lo .or. mid >= hi) exit
      if (flume_circle_alone(xi, r, mid, cos(mid), sin(mid)) .eqv. at_lo) then
        lo = mid
      else
        hi = mid
      end if
    end do
    mid = lo
    do k = 1, 8
      call compare_at(flume, mid, same, alone)
      mid = nearest(mid, -1.0_wp)
    end do
    mid = hi
    do k = 1, 8
      call compare_at(flume, mid, same, alone)
      mid = nearest(mid, 1.0_wp)
    end do
  end subroutine border

  !> The flume's section as evaluated before the shortcut: both joints'
  !> logistic weights (exp), the walls and the circle, Leibniz in v.
  function whole_blend(flume, v, order) result(p)
    type(flume_section_t), intent(in) :: flume
    real(wp), intent(in) :: v
    integer, intent(in) :: order
    type(section_point_t) :: p
    real(wp) :: lam(0:3, 2), w(0:3, 3), part(2, 0:3, 3), xi, r
    integer :: k, m, j
    r = flume%radius
    xi = logistic_rate(0.0_wp, flume%transition)
    call logistic(v, 0.0_wp, xi, lam(:, 1))
    call logistic(v, pi, xi, lam(:, 2))
    call blend_weights(lam, w)
    part = 0
    part(:, 0, 1) = [-r, -r*v];        part(:, 1, 1) = [0.0_wp, -r]
    part(:, 0, 2) = [-r*cos(v), -r*sin(v)]
    part(:, 1, 2) = [r*sin(v), -r*cos(v)]
    part(:, 2, 2) = [r*cos(v), r*sin(v)]
    part(:, 3, 2) = [-r*sin(v), r*cos(v)]
    part(:, 0, 3) = [r, r*(v - pi)];   part(:, 1, 3) = [0.0_wp, r]
    p%order = order
    p%s = 0
    do k = 0, order
      do j = 1, 3
        do m = 0, k
          p%s(:, 0, k) = p%s(:, 0, k) + binom(m, k)*w(m, j)*part(:, k - m, j)
        end do
      end do
    end do
  end function whole_blend

  function fmt(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(f0.1)') x
    text = trim(buf)
  end function fmt
end program test_flume_circle_alone

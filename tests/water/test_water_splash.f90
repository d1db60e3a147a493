!> Where the curve-entry term of (4.7) takes more of the water's speed than a
!> splash could (water_curve_entry splash_bends, splash_note; curve_entry_note), on recorded
!> curvatures of known shape: a bump chi = c sin^2(pi (s - s0)/L) between two
!> straights rises by c and turns the centreline by c L/2 (the trapezoid rule
!> is exact to rounding for it over the whole bump, sampled every 0.01 m);
!> over it the term alone keeps exp(-f3 c/m_w) of the speed, a splash at
!> least cos(c L/2). Checked:
!> - a 12 deg bend in 2 m (c = 0.2094 1/m; bowl.nml's at 51 m turns from
!>   14 to 2 deg in a 2 m transition) reported with its place, rise, turn
!>   and loss;
!> - the same rise over a longer bend (L = 10 m, turn 1.5 rad: a splash
!>   could take 93 %) not reported, over L = 4 m (turn 0.6 rad, 17.5 %)
!>   reported: the bound decides, not the rise alone;
!> - a horizontal curve (a rise to 0.25 1/m held to the end, 8 m) not
!>   reported;
!> - a ripple taking 0.5 % (a splash could take 0.001 %) not reported: under
!>   1 %;
!> - a tighter curve inside a curve: only the turn beyond the outer curve
!>   counts (turn = 0.125 rad, not the 1 rad of the whole), and the rise is
!>   the inner one's;
!> - the note names every place (numbers below 1 with their 0) and is
!>   empty without one;
!> - curve_entry_note (a loss over 50 %) writes its rise and places below
!>   1 with their 0.
program test_water_splash
  use base_kinds, only: wp
  use base_constants, only: pi
  use testing, only: check, check_close, finish_tests
  use water_series, only: water_series_t
  use water_curve_entry, only: curve_entry_t, splash_bends, splash_note, curve_entry_note
  implicit none (type, external)
  real(wp), parameter :: f3 = 0.979822_wp, h = 0.01_wp
  type(curve_entry_t), allocatable :: places(:)
  type(water_series_t) :: s
  character(len=:), allocatable :: note

  ! a 12 deg bend over 2 m between two straights, 5 m after the start
  s = bumps([5.0_wp], [2.0_wp], [12*pi/180/1.0_wp], 0.0_wp, 0.0_wp, 12.0_wp)
  places = splash_bends(s, f3, 1.0_wp)
  call check(size(places) == 1, 'the 12 deg bend reported once')
  if (size(places) == 1) then
    call check_close(places(1)%from, 5.0_wp, 0.0_wp, 1e-12_wp, 'where it starts')
    call check_close(places(1)%to, 7.0_wp, 0.0_wp, 1e-12_wp, 'where it ends (the curvature back at 0)')
    call check_close(places(1)%rise, 12*pi/180, 1e-13_wp, 0.0_wp, 'its rise c')
    call check_close(places(1)%turn, 12*pi/180, 1e-12_wp, 0.0_wp, 'its turn c L/2 = 12 deg')
    call check_close(places(1)%speed_kept, exp(-f3*12*pi/180), 1e-13_wp, 0.0_wp, 'the speed kept, exp(-f3 c/m_w)')
  end if
  note = splash_note(s, f3)
  call check(index(note, 'at arc length 5.00 to 7.00 m (18.6 % in a bend of 12.0 deg, a splash 2.2 %)') > 0, &
             'the note names the place, the loss, the turn and the bound: '//note)

  ! a 4 deg bend in 2 m: a splash could take 0.2 % (written with its 0), the term 6.6 %
  s = bumps([3.0_wp], [2.0_wp], [4*pi/180], 0.0_wp, 0.0_wp, 8.0_wp)
  note = splash_note(s, f3)
  call check(index(note, 'at arc length 3.00 to 5.00 m (6.6 % in a bend of 4.0 deg, a splash 0.2 %)') > 0, &
             'a 4 deg bend: '//note)

  ! curve_entry_note (the term takes 54 %, over its 50 %) over a bump of 0.8 1/m at 0.25 m: numbers below
  ! 1 with their 0 (5aceca2; before it "rises by .800 1/m from arc length .25 to .50 m")
  s = bumps([0.25_wp], [0.5_wp], [0.8_wp], 0.0_wp, 0.0_wp, 2.0_wp)
  note = curve_entry_note(s, f3)
  call check(index(note, 'the centreline''s curvature rises by 0.800 1/m from arc length 0.25 to 0.50 m: ') == 1 &
             .and. index(note, 'alone takes 54 % of the water''s speed') > 0, 'the curve-entry note: '//note)

  ! the same rise over 10 m (turn 1.5 rad) is within a splash; over 4 m (0.6 rad) not
  s = bumps([2.0_wp, 20.0_wp], [10.0_wp, 4.0_wp], [0.3_wp, 0.3_wp], 0.0_wp, 0.0_wp, 30.0_wp)
  places = splash_bends(s, f3, 1.0_wp)
  call check(size(places) == 1, 'of two bends of the same rise only the short one reported')
  if (size(places) == 1) then
    call check_close(places(1)%from, 20.0_wp, 0.0_wp, 1e-12_wp, 'the short bend')
    call check_close(places(1)%turn, 0.6_wp, 1e-12_wp, 0.0_wp, 'its turn 0.6 rad')
  end if

  ! a horizontal curve: the curvature rises to 0.25 1/m in 1 m and stays 8 m (turn > 90 deg)
  s = curve_held(0.25_wp, 6.0_wp)
  places = splash_bends(s, f3, 1.0_wp)
  call check(size(places) == 0, 'a curve of 0.25 1/m held over 6 m not reported')
  call check(len(splash_note(s, f3)) == 0, 'and no note')

  ! a ripple: the term takes 0.5 % (< 1 %), though more than a splash could (0.001 %)
  s = bumps([3.0_wp], [2.0_wp], [0.005_wp], 0.0_wp, 0.0_wp, 8.0_wp)
  call check(size(splash_bends(s, f3, 1.0_wp)) == 0, 'a ripple under 1 % of the speed not reported')

  ! a tighter curve (0.25 1/m) inside a curve of 0.125 1/m: the turn beyond the outer curve
  s = bumps([4.0_wp], [2.0_wp], [0.125_wp], 0.125_wp, 1.0_wp, 10.0_wp)
  places = splash_bends(s, f3, 1.0_wp)
  call check(size(places) == 1, 'the tighter curve inside a curve reported (once; not the outer curve)')
  if (size(places) == 1) then
    call check_close(places(1)%from, 4.0_wp, 0.0_wp, 1e-12_wp, 'where the tighter curve starts')
    call check_close(places(1)%rise, 0.125_wp, 1e-13_wp, 0.0_wp, 'its rise beyond the outer curve')
    call check_close(places(1)%turn, 0.125_wp, 1e-12_wp, 0.0_wp, 'its turn beyond the outer curve')
  end if
  call finish_tests('test_water_splash')

contains

  !> Records every h m over [0, total]: a curvature of `base` from `base_from`
  !> on (0 before), plus c(k) sin^2(pi (s - s0(k))/L(k)) over each bump; the
  !> bumps' ends and middles fall on records (x counted in records: exactly
  !> 0, 1/2 and 1 there).
  function bumps(s0, L, c, base, base_from, total) result(series)
    real(wp), intent(in) :: s0(:), L(:), c(:), base, base_from, total
    type(water_series_t) :: series
    integer :: i, k
    series%n = nint(total/h) + 1
    allocate (series%arc_length(series%n), series%curvature(series%n))
    do i = 1, series%n
      series%arc_length(i) = (i - 1)*h
      series%curvature(i) = merge(base, 0.0_wp, i - 1 >= nint(base_from/h))
      do k = 1, size(s0)
        associate (x => real(i - 1 - nint(s0(k)/h), wp)/nint(L(k)/h))
          if (x > 0 .and. x < 1) series%curvature(i) = series%curvature(i) + c(k)*sin(pi*x)**2
        end associate
      end do
    end do
  end function bumps

  !> A curve of curvature c entered over 1 m (sin^2 rise) and held over `held` m.
  function curve_held(c, held) result(series)
    real(wp), intent(in) :: c, held
    type(water_series_t) :: series
    integer :: i
    series%n = nint((3 + held)/h) + 1
    allocate (series%arc_length(series%n), series%curvature(series%n))
    do i = 1, series%n
      series%arc_length(i) = (i - 1)*h
      associate (x => series%arc_length(i) - 1)
        series%curvature(i) = c*merge(0.0_wp, merge(sin(pi*x/2)**2, 1.0_wp, x < 1), x <= 0)
      end associate
    end do
  end function curve_held
end program test_water_splash

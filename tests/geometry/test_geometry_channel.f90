!> The closed-form channels from their descriptions (geometry_channel): the
!> default description is &channel's default straight tube, and each kind
!> builds the tube its constructor gives (the same points and partials bit
!> for bit); a folding S-bend, helix turns through each other, a turn sense
!> not +-1, a helix radius within the tube's and an unknown kind are refused,
!> naming the value at fault. No io: a library caller's path.
program test_geometry_channel
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_tube, only: tube_surface_t, new_straight_tube, new_helix_tube, new_s_bend_tube
  use geometry_channel, only: channel_description_t, build_channel
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(channel_description_t) :: d
  type(tube_surface_t) :: built, expected
  type(status_t) :: st, st_expected
  character(len=:), allocatable :: variable

  call build_channel(d, built, st)
  expected = new_straight_tube(0.5_wp, 10*pi/180, 50.0_wp, st_expected)
  call check(st%ok() .and. st_expected%ok(), 'default: built '//st%text())
  call check(same_tube(built, expected), 'default: the straight tube, radius 0.5 m, 10 deg, 50 m')

  d = channel_description_t(kind='helix', radius=0.4_wp, helix_radius=2.0_wp, pitch=0.5_wp, turn_sense=-1.0_wp, &
                            turns=1.5_wp)
  call build_channel(d, built, st)
  expected = new_helix_tube(0.4_wp, 2.0_wp, 0.5_wp, -1.0_wp, 2*pi*1.5_wp, st_expected)
  call check(st%ok() .and. same_tube(built, expected), 'helix: its constructor''s tube '//st%text())

  d = channel_description_t(kind='s_bend', radius=0.3_wp, amplitude=-1.0_wp, wavenumber=0.5_wp, slope=0.2_wp, &
                            length=12.0_wp)
  call build_channel(d, built, st)
  expected = new_s_bend_tube(0.3_wp, -1.0_wp, 0.5_wp, 0.2_wp, 12.0_wp, st_expected)
  call check(st%ok() .and. same_tube(built, expected), 's_bend: its constructor''s tube '//st%text())

  ! curvature a k^2 = 6 1/m against the radius 0.5 m: it folds
  d = channel_description_t(kind='s_bend', amplitude=1.5_wp, wavenumber=2.0_wp)
  call build_channel(d, built, st, variable)
  call check(.not. st%ok() .and. index(st%text(), 'fold') > 0 .and. variable == '', &
             'folding s_bend refused, the tube as a whole: '//st%text())

  ! 0.05 m/rad: a turn 0.31 m below the last, the tube 1 m across
  d = channel_description_t(kind='helix', pitch=0.05_wp)
  st = status_t()
  call build_channel(d, built, st, variable)
  call check(.not. st%ok() .and. index(st%text(), 'passes through itself') > 0 .and. variable == '', &
             'helix turns through each other refused: '//st%text())

  ! the helix constructor takes the sign of turn_sense: 0.5 would be a silent +1
  d = channel_description_t(kind='helix', turn_sense=0.5_wp)
  st = status_t()
  call build_channel(d, built, st, variable)
  call check(.not. st%ok() .and. st%text() == 'turn_sense = 0.5 is not allowed: must be +1 or -1' .and. &
             variable == 'turn_sense', 'turn_sense 0.5 refused: '//st%text())

  d = channel_description_t(kind='helix', radius=0.5_wp, helix_radius=0.4_wp)
  st = status_t()
  call build_channel(d, built, st, variable)
  call check(.not. st%ok() .and. index(st%text(), 'helix_radius = 0.4 is not allowed: must exceed the tube '// &
             'radius 0.5 m') == 1 .and. variable == 'helix_radius', 'helix within the tube refused: '//st%text())

  d = channel_description_t(kind='spiral')
  st = status_t()
  call build_channel(d, built, st, variable)
  call check(.not. st%ok() .and. index(st%text(), 'spiral') > 0 .and. variable == 'kind', &
             'unknown kind refused: '//st%text())
  call finish_tests('test_geometry_channel')

contains

  !> The same points and partials (to order 3) at 25 places.
  logical function same_tube(a, b)
    type(tube_surface_t), intent(in) :: a, b
    type(surface_point_t) :: pa, pb
    type(status_t) :: sa, sb
    real(wp) :: u_min, u_max, v_min, v_max, u, v
    integer :: i, j
    same_tube = .true.
    call a%domain(u_min, u_max, v_min, v_max)
    do i = 0, 4
      do j = 0, 4
        u = u_min + (u_max - u_min)*i/4
        v = v_min + (v_max - v_min)*j/5
        call a%evaluate(u, v, 3, pa, sa)
        call b%evaluate(u, v, 3, pb, sb)
        same_tube = same_tube .and. sa%ok() .and. sb%ok() .and. all(pa%r == pb%r) .and. all(pa%ru == pb%ru) .and. &
                    all(pa%rv == pb%rv) .and. all(pa%ruu == pb%ruu) .and. all(pa%ruv == pb%ruv) .and. &
                    all(pa%rvv == pb%rvv) .and. all(pa%ruuu == pb%ruuu) .and. all(pa%rvvv == pb%rvvv)
      end do
    end do
  end function same_tube
end program test_geometry_channel

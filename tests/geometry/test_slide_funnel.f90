!> The funnel as an element of the slide chain (issue 26): the slide's flume
!> section widened about its bottom along the funnel and narrowed again
!> (geometry_funnel_section).
!>
!> geometry: a straight, a curve, a funnel and a straight, exact and fitted.
!> At both ends of the funnel and at the ends of its widest third the
!> surface's position, its first and second u-derivatives (the tangent and
!> curvature of every line v = const), r_v and the normal are continuous to
!> 1e-9 relative (each side 2e-6 m off the end carried across by its next
!> derivative); every partial derivative to the third matches central
!> differences of the one below (to 1e-6 relative); the bottom line
!> (v = pi/2) is the narrow slide's all along; in the widest third the section
!> is a circle of the funnel's radius resting on that bottom; impossible
!> funnels are refused with a message naming why. The funnel's extent (from
!> the flume's points kept at construction) is the general sampled extent to
!> the bit, and the widened walls' tops in the widest third.
!>
!> point mass (closed form): in the widest third of a level funnel of radius
!> R a frictionless point mass crossing the bottom at lateral speed V (and 1
!> m/s along) presses with N = m (g + V^2/R) there and swings up the wall to
!> V^2/(2 g) above the bottom and back; sliding down a slide through a curve
!> into a funnel and out, and swinging into a widening funnel, the normal
!> force changes between 1 ms records by little (no jump at the funnel's
!> ends) and the energy is kept to 1e-7. The normal force does not tell a
!> widening with a kink at its ends (a linear ramp: 0.011 g, 0.004 g) from
!> the smooth one (0.007 g, 0.004 g): the section changes over metres and
!> the mass crosses the kink in ms; the continuity check (and the energy,
!> whose speed jumps there) does.
program test_slide_funnel
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_surface, only: surface_point_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: slide_description_t, section_part_description_t, build_slide
  use geometry_funnel_section, only: funnel_section_t
  use geometry_tube, only: tube_surface_t
  use geometry_cross_section, only: sampled_extent
  use geometry_curve_frame, only: curve_frame_t
  use geometry_curve, only: curve_point_t
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: r_slide = 0.6_wp, wall = 0.4_wp, r_funnel = 2.5_wp, funnel_length = 18   ! m

  call funnel_geometry(.true.)
  call funnel_geometry(.false.)
  call funnel_refusals()
  call funnel_swing()
  call funnel_normal_force()
  call finish_tests('test_slide_funnel')

contains

  !> Straight, curve, funnel, straight with a flume section (exact or fitted).
  function funnel_slide(exact, radius, length, kind, n_parts) result(d)
    logical, intent(in) :: exact
    real(wp), intent(in) :: radius, length
    character(len=*), intent(in) :: kind
    integer, intent(in) :: n_parts
    type(slide_description_t) :: d
    d%kind = 'slide'
    d%elements%elements = [slide_element_t(kind='straight', length=8.0_wp, slope_deg=8.0_wp), &
                           slide_element_t(kind='curve', radius=6.0_wp, angle_deg=90.0_wp, slope_deg=6.0_wp), &
                           slide_element_t(kind='funnel', length=length, slope_deg=3.0_wp, radius=radius), &
                           slide_element_t(kind='straight', length=6.0_wp, slope_deg=6.0_wp)]
    d%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%elements%transition_length = 2
    d%elements%exact = exact
    allocate (d%section%parts(n_parts))
    d%section%parts = section_part_description_t(kind=kind, radius=r_slide, wall=wall)
    if (n_parts > 1) then
      d%section%transition_midpoint = [4.0_wp]
      d%section%transition_end = [5.0_wp]
    end if
  end function funnel_slide

  subroutine funnel_geometry(exact)
    logical, intent(in) :: exact
    type(tube_surface_t) :: slide
    type(status_t) :: st
    type(surface_point_t) :: p, q, b
    type(curve_frame_t) :: f
    type(curve_point_t) :: c
    real(wp) :: ends(4), u, v, h, worst_jump, worst_fd, worst_bottom, worst_circle, a(0:3), centre(3)
    character(len=:), allocatable :: label
    integer :: j, k, i
    label = merge('exact ', 'fitted', exact)
    call build_slide(funnel_slide(exact, r_funnel, funnel_length, 'flume', 1), slide, st)
    call check(st%ok(), 'funnel slide built ('//label//'): '//st%text())
    if (.not. st%ok()) return
    select type (s => slide%section)
    type is (funnel_section_t)
      ends = s%u_ends(:, 1)
      call check(size(s%scale) == 1 .and. abs(s%scale(1) - r_funnel/r_slide) < 1e-14_wp, &
                 'one funnel, widened to its radius ('//label//')')
      call s%scale_at((ends(2) + ends(3))/2, a)
      call check_close(a(0), r_funnel/r_slide, 1e-14_wp, 0.0_wp, 'the widest third scales the section by R/r')
      call funnel_extent_checks(s, label)
    class default
      call check(.false., 'the funnel slide''s section is a funnel section ('//label//')')
      return
    end select
    ! continuity across the funnel's ends and its widest third's
    worst_jump = 0
    do k = 1, 4
      do j = 0, 8
        v = -wall/r_slide + (pi + 2*wall/r_slide)*j/8
        ! each side carried across by its own next derivative: what is left
        ! is a jump, or (2 h)^2/2 of the derivative after, ~1e-11 here
        h = 1e-7_wp*max(1.0_wp, abs(ends(k)))
        call slide%evaluate(ends(k) - h, v, 3, p, st)
        call slide%evaluate(ends(k) + h, v, 3, q, st)
        worst_jump = max(worst_jump, rel(p%r + 2*h*p%ru, q%r), rel(p%ru + 2*h*p%ruu, q%ru), &
                         rel(p%ruu + 2*h*p%ruuu, q%ruu), rel(p%rv + 2*h*p%ruv, q%rv), &
                         rel(unit(cross(p%ru + 2*h*p%ruu, p%rv + 2*h*p%ruv)), unit(cross(q%ru, q%rv))))
      end do
    end do
    print '(a, a, es10.3)', label, ': largest jump at the funnel''s ends (r, r_u, r_uu, r_v, normal): ', worst_jump
    call check(worst_jump <= 1e-9_wp, 'the funnel''s ends are C2 ('//label//'): '//real_text(worst_jump))
    ! derivatives against central differences, in the widening and narrowing
    worst_fd = 0
    do i = 1, 6
      u = ends(1) + (ends(4) - ends(1))*(i - 0.5_wp)/6
      do j = 1, 5
        v = -wall/r_slide + (pi + 2*wall/r_slide)*j/6
        call fd_errors(slide, u, v, worst_fd)
      end do
    end do
    print '(a, a, es10.3)', label, ': largest derivative error against differences: ', worst_fd
    call check(worst_fd <= 1e-6_wp, 'the funnel''s derivatives against differences ('//label//'): '// &
               real_text(worst_fd))
    ! the bottom line is the narrow slide's (the centerline's, r below); in
    ! the widest third the flume's circle has the funnel's radius and rests on it
    worst_bottom = 0
    worst_circle = 0
    do i = 0, 20
      u = ends(1) + (ends(4) - ends(1))*i/20
      call slide%frame(u, 0, f, st, c)
      call slide%evaluate(u, pi/2, 0, b, st)
      worst_bottom = max(worst_bottom, norm2(b%r - (c%d(:, 0) - r_slide*f%z(:, 0))))
      if (u < ends(2) .or. u > ends(3)) cycle
      centre = c%d(:, 0) + (r_funnel - r_slide)*f%z(:, 0)
      do j = 1, 7   ! away from the flume's joints with its walls (v = 0, pi)
        call slide%evaluate(u, pi*j/8, 0, p, st)
        worst_circle = max(worst_circle, abs(norm2(p%r - centre) - r_funnel))
      end do
    end do
    print '(a, a, 2es10.3)', label, ': bottom line off the slide''s, widest section off its circle (m): ', &
      worst_bottom, worst_circle
    call check(worst_bottom <= 1e-9_wp, 'the funnel''s bottom is the slide''s bottom line ('//label//'): '// &
               real_text(worst_bottom)//' m')
    call check(worst_circle <= 1e-9_wp, 'the widest third is a circle of the funnel''s radius ('//label//'): '// &
               real_text(worst_circle)//' m')
  end subroutine funnel_geometry

  !> The funnel's extent (the tube's fold and clearance checks), taken from
  !> the base's points kept at construction, is the general sampled extent
  !> (every point evaluated through funnel_evaluate) to the bit at every u
  !> across the slide; in the widest third it is the widened flume's walls'
  !> tops, |b + A (s0 - b)| at s0 = [-r, wall] (b = [0, -r], A = R/r), and
  !> before the funnel the flume's own.
  subroutine funnel_extent_checks(s, label)
    type(funnel_section_t), intent(in) :: s
    character(len=*), intent(in) :: label
    real(wp) :: u, scale
    integer :: i, mismatches
    mismatches = 0
    do i = 0, 400
      u = s%u_ends(1, 1) - 10 + (s%u_ends(4, 1) - s%u_ends(1, 1) + 20)*i/400
      if (s%extent(u) /= sampled_extent(s, u)) mismatches = mismatches + 1
    end do
    call check(mismatches == 0, 'the funnel''s extent from the kept points is the sampled extent, bit for bit ('// &
               label//'): '//real_text(real(mismatches, wp))//' of 401 differ')
    scale = r_funnel/r_slide
    call check_close(s%extent((s%u_ends(2, 1) + s%u_ends(3, 1))/2), hypot(scale*r_slide, scale*(r_slide + wall) - &
                     r_slide), 0.0_wp, 1e-9_wp, 'the widest third''s extent: the widened walls'' tops ('//label//')')
    call check_close(s%extent(s%u_ends(1, 1) - 1), hypot(r_slide, wall), 0.0_wp, 1e-9_wp, &
                     'the extent before the funnel: the flume''s ('//label//')')
  end subroutine funnel_extent_checks

  !> The largest relative error of the partials at (u, v) against central
  !> differences of the order below (h = 1e-5 m: truncation h^2 ~ 1e-10
  !> relative, rounding 1e-16/1e-5).
  subroutine fd_errors(slide, u, v, worst)
    type(tube_surface_t), intent(in) :: slide
    real(wp), intent(in) :: u, v
    real(wp), intent(inout) :: worst
    real(wp), parameter :: h = 1e-5_wp
    type(surface_point_t) :: p, up, um, vp, vm
    type(status_t) :: st
    call slide%evaluate(u, v, 3, p, st)
    call slide%evaluate(u + h, v, 3, up, st)
    call slide%evaluate(u - h, v, 3, um, st)
    call slide%evaluate(u, v + h, 3, vp, st)
    call slide%evaluate(u, v - h, 3, vm, st)
    worst = max(worst, rel(p%ru, (up%r - um%r)/(2*h)), rel(p%ruu, (up%ru - um%ru)/(2*h)), &
                rel(p%ruuu, (up%ruu - um%ruu)/(2*h)), rel(p%ruv, (up%rv - um%rv)/(2*h)), &
                rel(p%ruuv, (up%ruv - um%ruv)/(2*h)), rel(p%ruvv, (up%rvv - um%rvv)/(2*h)), &
                rel(p%ruv, (vp%ru - vm%ru)/(2*h)), rel(p%rvv, (vp%rv - vm%rv)/(2*h)))
  end subroutine fd_errors

  !> What cannot be a funnel is refused, saying why.
  subroutine funnel_refusals()
    call refused(funnel_slide(.true., 0.5_wp, funnel_length, 'flume', 1), &
                 'a funnel widens the slide''s flume section of radius 0.6')
    call refused(funnel_slide(.true., r_funnel, 6.0_wp, 'flume', 1), 'its walls flaring at')
    call refused(funnel_slide(.true., r_funnel, funnel_length, 'ellipse', 1), 'one circle or flume section')
    call refused(funnel_slide(.true., r_funnel, funnel_length, 'flume', 2), 'blended with others')
  end subroutine funnel_refusals

  subroutine refused(d, words)
    type(slide_description_t), intent(in) :: d
    character(len=*), intent(in) :: words
    type(tube_surface_t) :: slide
    type(status_t) :: st
    call build_slide(d, slide, st)
    call check(.not. st%ok() .and. index(st%text(), words) > 0, 'refused ('//words//'): '//st%text())
  end subroutine refused

  !> A level funnel (straights around it level too: u is the arc length):
  !> in its widest third (u 14 .. 24) a frictionless mass crosses the bottom
  !> at V = 3 m/s across and 1 m/s along: N = m (g + V^2/R) at once, and it
  !> climbs V^2/(2 g) = 0.459 m up the wall of radius 2.5 m and comes back
  !> within a swing (~1.7 s, 1.7 m along: still in the widest third).
  subroutine funnel_swing()
    real(wp), parameter :: lateral = 3, g = standard_gravity
    type(point_mass_t), target :: model
    type(point_mass_state_t) :: state
    type(ode_integrator_t) :: integrator
    type(ode_options_t) :: options
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, z_bottom, highest, u_start
    integer :: k
    logical :: at_root, back
    u_start = 17
    call build(level_input(u_start, lateral/r_funnel, 1.0_wp), model, y0, options, st)
    if (.not. st%ok()) return
    call model%state(y0, state, st)
    print '(a, 2es13.5)', 'normal force at the bottom of the widest third, expected m (g + V^2/R): ', &
      abs(state%normal_force), g + lateral**2/r_funnel
    ! the state's own evaluation: only rounding
    call check_close(abs(state%normal_force), g + lateral**2/r_funnel, 1e-9_wp, 0.0_wp, &
                     'N = m (g + V^2/R) crossing the bottom of the funnel''s widest third')
    z_bottom = state%position(3)
    highest = z_bottom
    back = .false.
    call integrator%start(model, 0.0_wp, y0, options, st)
    do k = 1, 4000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      highest = max(highest, state%position(3))
      if (k > 100 .and. abs(state%position(3) - z_bottom) < 1e-3_wp) then
        back = .true.
        exit
      end if
    end do
    call integrator%destroy()
    print '(a, 2es13.5)', 'climb up the funnel''s wall, expected V^2/(2 g): ', highest - z_bottom, lateral**2/(2*g)
    ! rtol = atol = 1e-10 over ~1000 steps: 1e-7 m; the maximum sampled
    ! every 1 ms near the turning point (vertical speed ~ g t): g (0.5 ms)^2/2 ~ 1.2e-6 m
    call check_close(highest - z_bottom, lateral**2/(2*g), 0.0_wp, 5e-6_wp, &
                     'the mass climbs V^2/(2 g) up the funnel''s wall')
    call check(back .and. y(1) < 24, 'the mass swings back to the bottom within the widest third')
  end subroutine funnel_swing

  subroutine build(text, model, y0, options, st)
    character(len=*), intent(in) :: text
    type(point_mass_t), intent(out) :: model
    real(wp), allocatable, intent(out) :: y0(:)
    type(ode_options_t), intent(out) :: options
    type(status_t), intent(out) :: st
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    call input_from_text('<test>', text, input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    options = solver%options
    call check(st%ok(), 'funnel point mass built: '//st%text())
  end subroutine build

  function level_input(u0, dv0, du0) result(text)
    real(wp), intent(in) :: u0, dv0, du0
    character(len=:), allocatable :: text
    text = '&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-10, atol = 1e-10 /'//nl// &
      '&surface kind = ''slide'' /'//nl//'&geometry kind = ''slide'' /'//nl// &
      '&slide_elements n_elements = 3, transition_length = 2, centerline_kind = ''exact'','// &
      ' kind = ''straight'', ''funnel'', ''straight'', length = 4, 30, 4, slope_deg = 0, 0, 0,'// &
      ' radius = 0, 2.5, 0 /'//nl// &
      '&cross_section kind = ''flume'', radius = 0.6, wall = 0.4 /'//nl// &
      '&point_mass u0 = '//real_text(u0)//', v0 = 1.5707963267948966, du0 = '//real_text(du0)//', dv0 = '// &
      real_text(dv0)// &
      ', friction = ''none'' /'
  end function level_input

  !> The largest change of N between 1 ms records, in g: down the slide of
  !> funnel_slide (flume, exact) from the curve's start on the bottom at
  !> 5 m/s (the mass rides up the curve's outer wall, swings across the
  !> funnel and leaves it), and into the level funnel of level_input at
  !> 4 m/s swinging across the narrow flume (2 m/s across the bottom: 48 deg
  !> up its walls) as it widens.
  subroutine funnel_normal_force()
    real(wp) :: jump
    character(len=:), allocatable :: text
    text = '&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-10, atol = 1e-10 /'//nl// &
      '&surface kind = ''slide'' /'//nl//'&geometry kind = ''slide'' /'//nl// &
      '&slide_elements n_elements = 4, start = 0, 0, 10, transition_length = 2, centerline_kind = ''exact'','// &
      ' kind = ''straight'', ''curve'', ''funnel'', ''straight'', length = 8, 0, 18, 6,'// &
      ' slope_deg = 8, 6, 3, 6, radius = 0, 6, 2.5, 0, angle_deg = 0, 90, 0, 0 /'//nl// &
      '&cross_section kind = ''flume'', radius = 0.6, wall = 0.4 /'//nl// &
      '&point_mass u0 = 7, v0 = 1.5707963267948966, du0 = 5, dv0 = 0, friction = ''none'' /'
    ! past the funnel's end and the joint's transition
    call slide_through(text, 8 + 6*pi/2 + 18 + 1.5_wp, jump)
    print '(a, es10.3, a)', 'largest change of N between 1 ms records, curve into funnel: ', jump, ' g'
    ! the swing across the flume at the curve's end (omega ~ sqrt(N/r) ~ 5 1/s
    ! on N ~ 1.5 g, amplitude ~ N) changes N by ~ 0.01 g per ms; the widening
    ! changes the wall's curvature 1/r -> 1/R smoothly over 6 m (at 5-8 m/s,
    ! ~1 s): no more. Bound 0.05 g.
    call check(jump <= 0.05_wp, 'no jump of the normal force through the funnel: '//real_text(jump)//' g')
    call slide_through(level_input(1.0_wp, 2/r_slide, 4.0_wp), 15.0_wp, jump)
    print '(a, es10.3, a)', 'largest change of N between 1 ms records, swinging into the widening: ', jump, ' g'
    ! swinging across the narrow flume (omega = sqrt(g/r) ~ 4 1/s, N between
    ! g cos(48 deg) and g + V^2/r ~ 1.7 g): ~0.01 g per ms. Bound 0.05 g
    call check(jump <= 0.05_wp, 'no jump of the normal force swinging into the widening funnel: '// &
               real_text(jump)//' g')
  end subroutine funnel_normal_force

  subroutine slide_through(text, u_end, jump)
    character(len=*), intent(in) :: text
    real(wp), intent(in) :: u_end
    real(wp), intent(out) :: jump
    real(wp) :: energy0, drift
    type(point_mass_t), target :: model
    type(point_mass_state_t) :: state
    type(ode_integrator_t) :: integrator
    type(ode_options_t) :: options
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, n_prev
    integer :: k
    logical :: at_root
    jump = huge(1.0_wp)
    call build(text, model, y0, options, st)
    if (.not. st%ok()) return
    call model%state(y0, state, st)
    call integrator%start(model, 0.0_wp, y0, options, st)
    jump = 0
    drift = 0
    energy0 = state%kinetic_energy + state%potential_energy
    n_prev = state%normal_force
    do k = 1, 20000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      drift = max(drift, abs(state%kinetic_energy + state%potential_energy - energy0)/state%kinetic_energy)
      jump = max(jump, abs(state%normal_force - n_prev)/standard_gravity)
      n_prev = state%normal_force
      if (y(1) >= u_end) exit
    end do
    call integrator%destroy()
    call check(st%ok() .and. .not. at_root .and. y(1) >= u_end, 'the mass slid through the funnel: '//st%text())
    ! frictionless: the energy is kept to the integration's tolerances (rtol
    ! 1e-10 over ~1e4 steps); a widening with a kink at its ends changes the
    ! speed there (the surface's r_u jumps under the mass's (u', v'))
    print '(a, es10.3)', 'largest energy change relative to the kinetic energy: ', drift
    call check(drift <= 1e-7_wp, 'the frictionless mass keeps its energy through the funnel: '//real_text(drift))
  end subroutine slide_through

  pure real(wp) function rel(a, b)
    real(wp), intent(in) :: a(3), b(3)
    rel = norm2(a - b)/max(norm2(a), norm2(b), 1.0_wp)
  end function rel

  pure function unit(x) result(e)
    real(wp), intent(in) :: x(3)
    real(wp) :: e(3)
    e = x/norm2(x)
  end function unit

  function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(es23.16)') x
    text = trim(adjustl(buf))
  end function real_text
end program test_slide_funnel

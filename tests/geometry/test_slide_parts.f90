!> The slide parts beyond the tube's standard elements (issue 26), each in
!> the chain and each against a known answer.
!>
!> drop: the joints inside the drop (the fall's end, the curve-out's core
!> between its ramps) and the joint after it are continuous in position,
!> unit tangent and curvature vector to 1e-9 relative (a ramp far shorter
!> than the measure's step is caught by it; transition_length = 0 is
!> refused, test_sharp_joints); the core has the
!> radius asked; the height lost is the drop asked (against an independent
!> Simpson quadrature of the gradient); a frictionless point mass on the
!> bottom line starting at rest falls with v = sqrt(2 g h) and presses with
!> N = m (g cos(pitch) + v^2 kappa_b), kappa_b = kappa/(1 + r kappa) the
!> bottom line's curvature, at every record across the drop (in the core:
!> m (g cos + v^2/(R + r))), with no jump between records across the joints.
!>
!> halfpipe: an open U (the flume section: a semicircle of radius r and
!> vertical walls) with high walls on a horizontal straight: a frictionless
!> point mass crossing the bottom at V (and moving along the axis at U) rides
!> up one wall to the height V^2/(2 g) above the bottom, back through the
!> bottom at V and up the other wall to the same height (the along-axis
!> motion is decoupled: U stays).
!>
!> bowl (the point mass on a surface of revolution, as the chain has no bowl
!> element yet): the horizontal circle inside a spherical bowl of radius R at
!> the angle theta from the bottom (latitude -(90 deg - theta)): N cos(theta)
!> = m g and N sin(theta) = m v^2/rho, rho = R sin(theta), so
!> v^2 = g R sin(theta)^2/cos(theta), N = m g/cos(theta); inside a cone of
!> half-angle alpha at the height h above its apex: N sin(alpha) = m g and
!> N cos(alpha) = m v^2/rho, rho = h tan(alpha), so v^2 = g h (whatever
!> alpha), N = m g/sin(alpha). Started on its circle at that speed the mass
!> stays on it (height and speed to 1e-9 over two turns) and presses with that
!> N; started 1% faster it leaves the circle (the check can fail).
program test_slide_parts
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_curve, only: curve_point_t
  use geometry_surface, only: surface_point_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use numerics_ode, only: ode_integrator_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use scenario_fixtures, only: joint_jumps, start_point_mass, real_text
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: height = 10, top_deg = 80, radius = 8, exit_deg = 3, tube = 0.5_wp

  call drop_geometry()
  call drop_point_mass()
  call halfpipe_point_mass()
  call bowl_circles()
  call finish_tests('test_slide_parts')

contains

  !> The drop of `height` m at `top_deg` with a curve-out of `radius` m into a
  !> straight at `exit_deg`, then a curve.
  function drop_chain(transition, status) result(chain)
    real(wp), intent(in) :: transition
    type(status_t), intent(out) :: status
    type(element_chain_curve_t) :: chain
    type(slide_element_t) :: e(3)
    e(1) = slide_element_t(kind='drop', slope_deg=top_deg, radius=radius, drop=height)
    e(2) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=exit_deg)
    e(3) = slide_element_t(kind='curve', radius=8.0_wp, angle_deg=90.0_wp, slope_deg=4.0_wp)
    chain = new_element_chain(e, [0.0_wp, 0.0_wp, 14.0_wp], 0.0_wp, transition, status)
  end function drop_chain

  subroutine drop_geometry()
    type(element_chain_curve_t) :: chain, sharp
    type(status_t) :: st
    type(curve_point_t) :: p, q, r
    real(wp) :: joints(4), jump(3), kappa, a, b, x, ds, z_simpson, worst
    integer :: i, n
    chain = drop_chain(2.0_wp, st)
    call check(st%ok(), 'drop chain built: '//st%text())
    if (.not. st%ok()) return
    associate (d => chain%drop)
      call check(chain%starts_with_drop, 'the chain starts with its drop')
      ! the fall's end, the core's start and end, the drop's end (the joint to the straight)
      joints = [d%fall, d%fall + d%ramp_top, d%fall + d%ramp_top + d%core, d%total]
      call check(d%ramp_top > 0 .and. d%ramp_exit > 0 .and. d%core > 0 .and. d%fall > 0, 'the drop has all its pieces')
      call check_close(chain%ends(1), d%total, 0.0_wp, 0.0_wp, 'the drop is the first element, as long as its profile')
      call joint_jumps(chain, joints, 1/radius, jump)   ! relative to the curve-out's 1/R
      call check(jump(1) <= 1e-9_wp, 'drop joints: position continuous to 1e-9')
      call check(jump(2) <= 1e-9_wp, 'drop joints: unit tangent continuous to 1e-9')
      call check(jump(3) <= 1e-9_wp, 'drop joints: curvature continuous to 1e-9 of 1/R')
      ! each derivative against central differences of the one below, at
      ! scattered points across the drop (h = 1e-5 m: truncation ~h^2 c''''' ~1e-9,
      ! rounding ~eps/h ~1e-11 of the values)
      worst = 0
      do i = 1, 37
        x = d%total*(i - 0.5_wp)/37.3_wp
        call chain%evaluate(x, 4, p, st)
        call chain%evaluate(x + 1e-5_wp, 4, q, st)
        call chain%evaluate(x - 1e-5_wp, 4, r, st)
        do n = 1, 4
          worst = max(worst, norm2((q%d(:, n - 1) - r%d(:, n - 1))/2e-5_wp - p%d(:, n))/max(norm2(p%d(:, n)), 1.0_wp))
        end do
      end do
      call check(worst <= 1e-6_wp, 'drop: derivatives against central differences: '//real_text(worst))
      ! the pitch at the top and the core's radius
      call chain%evaluate(0.5_wp*d%fall, 2, p, st)
      call check_close(atan(-p%d(3, 1)/norm2(p%d(1:2, 1)))*180/pi, top_deg, 1e-12_wp, 0.0_wp, 'the fall''s slope')
      do i = 0, 4
        call chain%evaluate(joints(2) + (joints(3) - joints(2))*i/4.0_wp, 2, p, st)
        kappa = norm2(cross(p%d(:, 1), p%d(:, 2)))/norm2(p%d(:, 1))**3
        call check_close(kappa, 1/radius, 1e-12_wp, 0.0_wp, 'the curve-out''s core has the radius asked')
      end do
      ! the height lost against composite Simpson over the gradient -c'(3)
      ! (2 x 20000 intervals on smooth pieces: error ~ 1e-13 m)
      z_simpson = 0
      a = 0
      do i = 1, 4
        b = joints(i)
        ds = (b - a)/20000
        x = 0
        do n = 0, 20000
          call chain%evaluate(a + n*ds, 1, p, st)
          x = x + merge(1, merge(4, 2, mod(n, 2) == 1), n == 0 .or. n == 20000)*(-p%d(3, 1))
        end do
        z_simpson = z_simpson + x*ds/3
        a = b
      end do
      call chain%evaluate(0.0_wp, 0, p, st)
      call chain%evaluate(d%total, 0, q, st)
      call check_close(p%d(3, 0) - q%d(3, 0), height, 1e-12_wp, 0.0_wp, 'the drop loses the height asked')
      call check_close(z_simpson, height, 1e-10_wp, 0.0_wp, 'the height lost by an independent quadrature')
    end associate
    ! the same drop with ramps of 1e-12 m, far inside the measure's 2e-11 m:
    ! it sees the curvature change 1/R as a jump
    sharp = drop_chain(1e-12_wp, st)
    call check(st%ok(), 'nearly sharp drop chain built')
    associate (d => sharp%drop)
      call joint_jumps(sharp, [d%fall, d%total], 1/radius, jump)
    end associate
    call check(jump(3) > 0.9_wp, 'nearly sharp joints: the curvature jump is seen (the check can fail)')
    call check(jump(2) <= 1e-9_wp, 'nearly sharp joints: the tangent is still continuous')
    ! refusals
    call refused([slide_element_t(kind='straight', length=5.0_wp, slope_deg=5.0_wp), &
                  slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp)], 'only the first')
    call refused([slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp)], 'an element after it')
    call refused([slide_element_t(kind='drop', slope_deg=80.0_wp, radius=20.0_wp, drop=5.0_wp), &
                  slide_element_t(kind='straight', length=5.0_wp, slope_deg=5.0_wp)], 'curve-out of radius')
    call refused([slide_element_t(kind='drop', slope_deg=88.0_wp, radius=8.0_wp, drop=10.0_wp), &
                  slide_element_t(kind='straight', length=5.0_wp, slope_deg=5.0_wp)], '[45.0, 85.0]')
  end subroutine drop_geometry

  subroutine refused(e, words)
    type(slide_element_t), intent(in) :: e(:)
    character(len=*), intent(in) :: words
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    chain = new_element_chain(e, [0.0_wp, 0.0_wp, 14.0_wp], 0.0_wp, 2.0_wp, st)
    call check(.not. st%ok() .and. index(st%text(), words) > 0, 'refused ('//words//'): '//st%text())
  end subroutine refused

  !> The point mass, frictionless, on the bottom line from rest at the top.
  subroutine drop_point_mass()
    real(wp) :: jump_smooth, jump_sharp, v_bottom, h_bottom, h_fallen
    call fall('2.0', jump_smooth, v_bottom, h_bottom, h_fallen)
    ! the bottom line is the centerline offset by r below it: it loses
    ! r (cos(exit) - cos(top)) more than the centerline's drop
    call check_close(h_bottom, height + tube*(cos(exit_deg*pi/180) - cos(top_deg*pi/180)), 1e-12_wp, 0.0_wp, &
                     'the bottom line''s drop')
    ! the mass starts 1e-4 m (horizontally, beyond the domain's edge margin)
    ! below the top: h is from its start, 6e-4 m less than from the top
    call check_close(v_bottom, sqrt(2*standard_gravity*h_fallen), 1e-8_wp, 0.0_wp, &
                     'the speed at the drop''s bottom is sqrt(2 g h)')
    call check_close(h_fallen, h_bottom, 1e-4_wp, 0.0_wp, 'the mass starts at the top')
    ! ramps of 5 mm (~0.4 ms at ~14 m/s, less than a record): the normal
    ! force changes by v^2/(R + r) between two records, yet the speed is
    ! still the fallen height's (the old sharp joints, transition_length = 0,
    ! broke it: the tube's r_u jumped there, and the speed with it)
    call fall('0.005', jump_sharp, v_bottom, h_bottom, h_fallen)
    call check_close(v_bottom, sqrt(2*standard_gravity*h_fallen), 1e-8_wp, 0.0_wp, &
                     'nearly sharp joints: the speed at the drop''s bottom is sqrt(2 g h)')
    ! a ramp turns kappa at most 35/16 of its mean rate: over ~0.14 s at ~14 m/s
    ! that is ~1.6e-2 of v^2/(R + r) per 1 ms record; a sharp joint jumps by 1
    call check(jump_smooth <= 0.03_wp, 'no jump of the normal force between records across the joints: '// &
               real_text(jump_smooth))
    call check(jump_sharp >= 0.5_wp, 'nearly sharp joints: the normal force jumps (the check can fail): '// &
               real_text(jump_sharp)//' (smooth '//real_text(jump_smooth)//')')
  end subroutine drop_point_mass

  subroutine bowl_circles()
    real(wp), parameter :: big = 3, theta = 50*pi/180, alpha = 35*pi/180, h = 1.2_wp   ! m, rad, rad, m
    real(wp) :: v, drift(2)
    character(len=40) :: text
    ! spherical bowl: u the longitude, v the latitude (the circle's: theta - 90 deg)
    v = sqrt(standard_gravity*big*sin(theta)**2/cos(theta))
    write (text, '(es23.16)') theta - pi/2
    call circle('&surface kind = ''sphere_zone'', radius = 3, latitude_min_deg = -89, latitude_max_deg = 0 /', &
                trim(text), v, big*sin(theta), standard_gravity/cos(theta), 'spherical bowl', drift)
    call check(drift(1) <= 1e-9_wp*big .and. drift(2) <= 1e-9_wp*v, 'spherical bowl: stays on its circle')
    call circle('&surface kind = ''sphere_zone'', radius = 3, latitude_min_deg = -89, latitude_max_deg = 0 /', &
                trim(text), 1.01_wp*v, big*sin(theta), -1.0_wp, 'spherical bowl 1% fast', drift)
    call check(drift(1) > 1e-3_wp*big, 'spherical bowl: 1% too fast leaves the circle (the check can fail)')
    ! conical bowl: u the angle about the axis, v the height above the apex
    v = sqrt(standard_gravity*h)
    write (text, '(es23.16)') h
    call circle('&surface kind = ''cone'', half_angle_deg = 35, z_min = 0.2, z_max = 3 /', trim(text), v, &
                h*tan(alpha), standard_gravity/sin(alpha), 'conical bowl', drift)
    call check(drift(1) <= 1e-9_wp*h .and. drift(2) <= 1e-9_wp*v, 'conical bowl: stays on its circle')
    call circle('&surface kind = ''cone'', half_angle_deg = 35, z_min = 0.2, z_max = 3 /', trim(text), &
                0.99_wp*v, h*tan(alpha), -1.0_wp, 'conical bowl 1% slow', drift)
    call check(drift(1) > 1e-3_wp*h, 'conical bowl: 1% too slow leaves the circle (the check can fail)')
  end subroutine bowl_circles

  !> The mass started at the profile parameter `v0` (text) with the speed
  !> `speed` along the circle of radius `rho`: over two turns the largest
  !> change of its height and of its speed (drift), and |N| against
  !> `normal` (per kg; not checked when negative).
  subroutine circle(surface, v0, speed, rho, normal, name, drift)
    character(len=*), intent(in) :: surface, v0, name
    real(wp), intent(in) :: speed, rho, normal
    real(wp), intent(out) :: drift(2)
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    character(len=32) :: rate
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, z0, worst, period
    integer :: k, n
    logical :: at_root, started
    drift = huge(1.0_wp)
    write (rate, '(es23.16)') speed/rho
    call start_point_mass('&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12 /'//nl//surface//nl// &
      '&point_mass u0 = 0, v0 = '//v0//', du0 = '//trim(rate)//', dv0 = 0, friction = ''none'' /', name, model, &
      integrator, y0, state, started)
    if (.not. started) return
    call check_close(state%speed, speed, 1e-14_wp, 0.0_wp, name//': the start speed')
    call check_close(norm2(state%position(1:2)), rho, 1e-14_wp, 0.0_wp, name//': the circle''s radius')
    z0 = state%position(3)
    period = 2*pi*rho/speed
    n = 400
    drift = 0
    worst = 0
    do k = 1, 2*n
      call integrator%advance(period*k/n, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      drift = max(drift, [abs(state%position(3) - z0), abs(state%speed - speed)])
      if (normal > 0) worst = max(worst, abs(abs(state%normal_force) - normal)/normal)
    end do
    call check(st%ok() .and. .not. at_root, name//': ran two turns: '//st%text())
    ! 1e-9: N is algebraic in the state, which the integrator keeps to ~1e-10
    if (normal > 0) call check(worst <= 1e-9_wp, name//': N = m g/cos(theta) (sphere), m g/sin(alpha) (cone)')
    call integrator%destroy()
  end subroutine circle

  !> Up one wall and back, then up the other: on a wall the motion is a free
  !> vertical throw (the wall is a vertical plane: N = 0), so the apex is the
  !> vertex of the parabola through the three records around the highest.
  subroutine halfpipe_point_mass()
    real(wp), parameter :: r = 2, wall = 2.5_wp, across = 8, along = 0.5_wp   ! m, m, m/s, m/s
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    character(len=32) :: rate
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, z(3), z_bottom, apex(2), e0, worst, v_min, v_max, h, drift
    integer :: k, walls, crossings
    logical :: at_root, rising, started
    write (rate, '(es23.16)') across/r
    call start_point_mass('&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12 /'//nl// &
      '&surface kind = ''slide'' /'//nl//'&geometry kind = ''slide'' /'//nl// &
      '&slide_elements n_elements = 1, kind = ''straight'', length = 20, slope_deg = 0, '// &
      'centerline_kind = ''exact'' /'//nl// &
      '&cross_section kind = ''flume'', radius = 2, wall = 2.5 /'//nl// &
      '&point_mass u0 = 2, v0 = 1.5707963267948966, du0 = 0.5, dv0 = '//trim(rate)//', friction = ''none'' /', &
      'halfpipe point mass', model, integrator, y0, state, started)
    if (.not. started) return
    call check_close(state%speed, hypot(across, along), 1e-14_wp, 0.0_wp, 'halfpipe: the start speed')
    z_bottom = state%position(3)
    e0 = state%kinetic_energy + state%potential_energy
    h = across**2/(2*standard_gravity)
    call check(h > r + 0.5_wp .and. h < r + wall, 'halfpipe: the apex lies on the wall, 0.5 m above its joint')
    call model%surface%domain(t, z(1), v_min, v_max)
    z = z_bottom
    walls = 0
    crossings = 0
    worst = 0
    drift = 0
    apex = 0
    rising = .true.
    do k = 1, 4000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      worst = max(worst, abs(state%kinetic_energy + state%potential_energy - e0))
      drift = max(drift, abs(state%velocity(1) - along))
      z = [z(2), z(3), state%position(3)]
      if (rising .and. z(3) < z(2)) then      ! z(2) is the highest record
        walls = walls + 1
        if (walls <= 2) apex(walls) = z(2) - (z(3) - z(1))**2/(8*(z(1) - 2*z(2) + z(3))) - z_bottom
      end if
      if (.not. rising .and. z(3) > z(2)) crossings = crossings + 1
      rising = z(3) >= z(2)
      if (walls == 2 .and. crossings == 2) exit
      if (abs(y(2) - v_min) < 1e-3_wp .or. abs(y(2) - v_max) < 1e-3_wp) exit
    end do
    call check(st%ok() .and. .not. at_root, 'halfpipe: ran without leaving the surface: '//st%text())
    call check(walls == 2, 'halfpipe: up one wall, back and up the other')
    call check_close(apex(1), h, 1e-9_wp, 0.0_wp, 'halfpipe: the height reached up the first wall is V^2/(2g)')
    call check_close(apex(2), h, 1e-9_wp, 0.0_wp, 'halfpipe: and up the other')
    call check(drift <= 1e-9_wp*along, 'halfpipe: the along-axis speed stays')
    ! 1e-9 of the kinetic energy (the point mass's acceptance is 1e-8: rtol 1e-12 over ~1e3 steps)
    call check(worst <= 1e-9_wp*0.5_wp*(across**2 + along**2), 'halfpipe: energy conserved')
    call integrator%destroy()
  end subroutine halfpipe_point_mass

  !> Runs the mass from rest down the drop (transition length `transition`),
  !> records every 1 ms: checks N against the closed form at each record in
  !> the drop; returns the largest change of N between records (in units of
  !> m v^2/(R + r)), the speed and the bottom line's drop at the drop's end.
  subroutine fall(transition, jump, v_bottom, h_bottom, v_start_height)
    character(len=*), intent(in) :: transition
    real(wp), intent(out) :: jump, v_bottom, h_bottom, v_start_height
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    type(element_chain_curve_t) :: chain
    type(curve_point_t) :: c
    type(surface_point_t) :: pt
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, z0, n_prev, worst, cos_pitch, kappa, kb, n_expected, z_end, length
    integer :: k
    logical :: at_root, inside, started
    read (transition, *) length
    chain = drop_chain(length, st)
    jump = huge(1.0_wp); v_bottom = 0; h_bottom = 0; v_start_height = 0
    call start_point_mass('&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12 /'//nl// &
      '&surface kind = ''slide'' /'//nl//'&geometry kind = ''slide'' /'//nl// &
      '&slide_elements n_elements = 3, start = 0, 0, 14, transition_length = '//transition//','// &
      ' centerline_kind = ''exact'', kind = ''drop'', ''straight'', ''curve'', length = 0, 6, 0,'// &
      ' slope_deg = 80, 3, 4, radius = 8, 0, 8, angle_deg = 0, 0, 90, drop = 10, 0, 0 /'//nl// &
      '&cross_section kind = ''circle'', radius = 0.5 /'//nl// &
      '&point_mass u0 = 1e-4, v0 = 1.5707963267948966, du0 = 0, dv0 = 0, friction = ''none'' /', &
      'drop point mass', model, integrator, y0, state, started)
    if (.not. started) return
    z0 = state%position(3)
    jump = 0
    worst = 0
    inside = .true.
    n_prev = state%normal_force
    do k = 1, 3000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      inside = inside .and. abs(y(2) - pi/2) <= 1e-9_wp
      if (state%speed > 1) jump = max(jump, abs(state%normal_force - n_prev)/(state%speed**2/(radius + tube)))
      n_prev = state%normal_force
      if (y(1) >= chain%drop%total) exit
      ! the closed form: the pitch from the velocity, the bottom line's curvature
      ! from the centerline's (a parallel curve r outside the centre of curvature)
      call chain%evaluate(y(1), 2, c, st)
      kappa = norm2(cross(c%d(:, 1), c%d(:, 2)))/norm2(c%d(:, 1))**3
      kb = kappa/(1 + tube*kappa)
      cos_pitch = norm2(state%velocity(1:2))/state%speed
      n_expected = standard_gravity*cos_pitch + state%speed**2*kb      ! mass 1 kg
      worst = max(worst, abs(abs(state%normal_force) - n_expected)/n_expected)
      call check_close(state%speed, sqrt(2*standard_gravity*(z0 - state%position(3))), &
                                                1e-8_wp, 0.0_wp, 'speed from the height fallen at '//real_text(y(1)))
      if (.not. st%ok()) exit
    end do
    call check(st%ok(), 'drop point mass ran: '//st%text())
    call check(y(1) >= chain%drop%total, 'the mass reached the drop''s end ('//transition//')')
    call check(inside, 'the mass stays on the bottom line (v = pi/2 to 1e-9)')
    ! 1e-8: the integrator's rtol 1e-12 over ~2000 steps; N is algebraic in the state
    call check(worst <= 1e-8_wp, 'N = m (g cos + v^2 kappa_b) across the drop ('//transition//')')
    ! at the drop's end: the speed from the bottom line's drop (energy), which
    ! the geometry check above ties to the drop asked
    call model%state(y, state, st)
    call model%surface%evaluate(chain%drop%total, pi/2, 0, pt, st)
    z_end = pt%r(3)
    v_bottom = sqrt(max(state%speed**2 - 2*standard_gravity*(z_end - state%position(3)), 0.0_wp))
    v_start_height = z0 - z_end
    call model%surface%evaluate(0.0_wp, pi/2, 0, pt, st)
    h_bottom = pt%r(3) - z_end
    call integrator%destroy()
  end subroutine fall

end program test_slide_parts

!> The body of the thesis's geometry optimisation (4.7, METHOD-PART2 E.2): a
!> rigid cuboid carried by a Darboux frame on the slide, built from the
!> mechanism elements (a surface joint and a mass element), 2 degrees of
!> freedom q = [u, v], no friction, no water; one ride from a start speed and
!> direction to the end of the slide, with the figures the optimisation needs:
!> the largest acceleration and the largest tipping lever arm.
!>
!> Frame: the Darboux frame with sigma = 1, alpha_u = 0, alpha_v = 1 (the
!> tube convention of thesis 4.2): x_D = r_v/|r_v| across the slide, z_D the
!> normal into the tube, y_D = z_D x x_D along the slide. The cuboid's long
!> side lies along y_D, its width along x_D, its height along z_D; its centre
!> of mass is com_height above the surface (along +z_D).
!>
!> Acceleration (4.49): the linear acceleration of the Darboux frame's origin
!> a_D (ACCELERATION_KINEMATIC, the thesis's words), or the felt specific
!> force a_D - g (ACCELERATION_FELT).
!> Lever arm (E.3): l = (M_r . y_D)/(F_r . z_D) with the slide's reaction on
!> the body at the Darboux frame, F_r = m (a_c - g) and
!> M_r = Theta_c alpha + omega x Theta_c omega + (c - r_D) x F_r
!> (design_ride_evaluation's tipping_lever_arm).
!> The lever arm exists only while the body is pressed (F_r . z_D > 0); on a
!> wall too steep for its speed the body would lift off. For the constraint
!> l <= l_max a measure that exists always is kept too, the tipping excess
!>   e = (|M_r . y_D| - l_max F_r . z_D)/(m |g|)   (m),
!> which is <= 0 exactly when the body is pressed and l <= l_max, and equals
!> l - l_max when the body is pressed by its weight.
!> Maxima over time: the largest sample at every output step and at the end,
!> refined by the parabola through it and its two neighbours (error O(dt^3)
!> instead of O(dt^2), so that the maxima change smoothly with the slide's
!> shape, as the optimiser's difference Jacobian needs). A lever arm of
!> huge() (no pressing) stays huge.
module design_cuboid_ride
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use base_vector, only: cross
  use base_text, only: format_short
  use geometry_surface, only: surface_t, surface_point_t
  use numerics_ode, only: ode_options_t
  use numerics_event_driver, only: event_system_t, driver_options_t, driver_result_t, drive, &
    EVENT_STOP, RECORD_START, DRIVE_EVENT_STOP, DRIVE_END_TIME
  use kinetostatics_surface_joint, only: new_surface_joint
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use design_ride_evaluation, only: tipping_lever_arm
  implicit none (type, external)
  private
  public :: cuboid_t, cuboid_start_t, cuboid_ride_options_t, cuboid_ride_t, cuboid_series_t
  public :: ride_cuboid, cuboid_inertia
  public :: ACCELERATION_KINEMATIC, ACCELERATION_FELT

  integer, parameter :: ACCELERATION_KINEMATIC = 1, ACCELERATION_FELT = 2

  !> Thesis 4.7: 90 kg, 1.8 x 0.5 x 0.2 m, centre of mass 0.1 m above the slide.
  type :: cuboid_t
    real(wp) :: mass = 90             !< kg
    real(wp) :: length = 1.8_wp       !< m, along the slide (y_D)
    real(wp) :: width = 0.5_wp        !< m, across (x_D)
    real(wp) :: height = 0.2_wp       !< m, along the normal (z_D)
    real(wp) :: com_height = 0.1_wp   !< m above the surface
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   !< m/s^2
  end type cuboid_t

  !> Where and how a ride starts: surface parameters, speed and its angle to
  !> r_u (the centerline direction) in the tangent plane, positive towards +v.
  type :: cuboid_start_t
    real(wp) :: u = 0                 !< centerline parameter
    real(wp) :: v = pi/2              !< rad, pi/2: the bottom of the section
    real(wp) :: speed = 0.5_wp        !< m/s
    real(wp) :: angle = 0             !< rad
  end type cuboid_start_t

  type :: cuboid_ride_options_t
    type(ode_options_t) :: ode = ode_options_t(rtol=1e-7_wp, atol=1e-7_wp)   !< see docs/design.md
    real(wp) :: output_step = 0.005_wp   !< s, sampling of the maxima (refined between samples)
    real(wp) :: t_end = 60               !< s, a bound; rides end at the slide's end
    integer :: acceleration = ACCELERATION_KINEMATIC
    real(wp) :: lever_limit = 0.25_wp    !< m, l_max of the tipping excess
    logical :: keep_series = .false.     !< keep the samples (for plots)
  end type cuboid_ride_options_t

  type :: cuboid_series_t
    integer :: n = 0
    real(wp), allocatable :: time(:), u(:), v(:), position(:, :), acceleration(:), lever_arm(:), speed(:)
    real(wp), allocatable :: normal_force(:)   !< N, F_r . z_D
  end type cuboid_series_t

  !> The figures of one ride.
  type :: cuboid_ride_t
    real(wp) :: max_acceleration = 0     !< m/s^2, the chosen kind
    real(wp) :: time_of_max = 0          !< s
    real(wp) :: u_of_max = 0
    real(wp) :: max_lever_arm = 0        !< m, max |l| (huge if the body lifts off)
    real(wp) :: time_of_max_lever = 0    !< s
    real(wp) :: max_tipping_excess = -huge(1.0_wp)   !< m, max e (see the module comment)
    real(wp) :: min_normal_force = huge(1.0_wp)      !< N, F_r . z_D
    logical :: lifts_off = .false.       !< F_r . z_D <= 0 at some sample
    real(wp) :: duration = 0             !< s, to the end of the slide
    real(wp) :: end_speed = 0            !< m/s
    real(wp) :: start_angle = 0          !< rad, of cuboid_start_t
    logical :: reached_end = .false.
    integer :: rhs_evaluations = 0
    type(cuboid_series_t) :: series
  end type cuboid_ride_t

  !> The largest of a sampled signal, refined by the parabola through the
  !> largest sample and its two neighbours once the sample after it is known.
  type :: running_max_t
    real(wp) :: value = -huge(1.0_wp), time = 0
    real(wp) :: best(2) = 0, best_time(2) = 0    !< the sample before the best one, and the best
    real(wp) :: last = 0, last_time = 0
    logical :: have_last = .false., refine_next = .false.
  end type running_max_t

  !> The ride as a model of the integration driver.
  type, extends(event_system_t) :: cuboid_model_t
    type(mechanism_t) :: mechanism
    type(mechanism_workspace_t) :: work   ! of the ride's mechanism computations
    integer :: frame = 0                 !< the Darboux frame
    type(cuboid_t) :: body
    real(wp) :: inertia(3, 3) = 0        !< kg m^2, about the centre of mass, D axes
    real(wp) :: u_end = 0
    real(wp) :: lever_limit = 0.25_wp
    integer :: kind = ACCELERATION_KINEMATIC
    logical :: keep = .false.
    type(running_max_t) :: acceleration, excess, lever
    type(cuboid_ride_t) :: out
  contains
    procedure :: rhs => cuboid_rhs
    procedure :: root_count => cuboid_root_count
    procedure :: roots => cuboid_roots
    procedure :: record => cuboid_record
  end type cuboid_model_t

contains

  !> Principal moments of a homogeneous cuboid about its centre, in the D axes
  !> (x: width, y: length, z: height).
  pure function cuboid_inertia(body) result(inertia)
    type(cuboid_t), intent(in) :: body
    real(wp) :: inertia(3, 3)
    inertia = 0
    inertia(1, 1) = body%mass*(body%length**2 + body%height**2)/12
    inertia(2, 2) = body%mass*(body%width**2 + body%height**2)/12
    inertia(3, 3) = body%mass*(body%length**2 + body%width**2)/12
  end function cuboid_inertia

  !> One ride of the cuboid on `slide` from `start` to u_end (the end of the
  !> slide). The slide is read only; each call builds its own mechanism
  !> (thread-safe).
  subroutine ride_cuboid(slide, body, start, u_end, options, ride, status)
    class(surface_t), intent(in) :: slide
    type(cuboid_t), intent(in) :: body
    type(cuboid_start_t), intent(in) :: start
    real(wp), intent(in) :: u_end
    type(cuboid_ride_options_t), intent(in) :: options
    type(cuboid_ride_t), intent(out) :: ride
    type(status_t), intent(out) :: status
    type(cuboid_model_t), target :: model
    type(driver_options_t) :: driver
    type(driver_result_t) :: result
    type(surface_point_t) :: p
    integer :: su, sv
    real(wp) :: e11, e12, e22, b1, b2, det, t_hat(3), c_hat(3), velocity(3), y0(4)

    model%body = body
    model%inertia = cuboid_inertia(body)
    model%u_end = u_end
    model%kind = options%acceleration
    model%lever_limit = options%lever_limit
    model%keep = options%keep_series
    model%frame = model%mechanism%add_frame('darboux')
    su = model%mechanism%add_scalar('u', start%u)
    sv = model%mechanism%add_scalar('v', start%v)
    call model%mechanism%add_element(new_surface_joint('slide', 1, model%frame, su, sv, slide, &
                                                       1.0_wp, 0.0_wp, 1.0_wp))
    call model%mechanism%add_element(new_mass_element('cuboid', model%frame, body%mass, model%inertia, &
                                                      [0.0_wp, 0.0_wp, body%com_height], body%gravity, status))
    call model%mechanism%set_coordinates([su, sv])
    if (status%ok()) call model%mechanism%finalize(status)
    if (.not. status%ok()) return

    ! start velocity: speed along cos(angle) t + sin(angle) c in the tangent
    ! plane (t along r_u, c the unit tangent towards +v normal to t), as u', v'
    call slide%evaluate(start%u, start%v, 1, p, status)
    if (.not. status%ok()) return
    t_hat = p%ru/norm2(p%ru)
    c_hat = p%rv - dot_product(p%rv, t_hat)*t_hat
    c_hat = c_hat/norm2(c_hat)
    velocity = start%speed*(cos(start%angle)*t_hat + sin(start%angle)*c_hat)
    e11 = dot_product(p%ru, p%ru); e12 = dot_product(p%ru, p%rv); e22 = dot_product(p%rv, p%rv)
    b1 = dot_product(p%ru, velocity); b2 = dot_product(p%rv, velocity)
    det = e11*e22 - e12**2
    y0 = [start%u, start%v, (e22*b1 - e12*b2)/det, (e11*b2 - e12*b1)/det]

    driver%ode = options%ode
    driver%output_step = options%output_step
    driver%t_end = options%t_end
    driver%progress_seconds = 0
    driver%label = 'cuboid ride'
    call drive(model, y0, driver, result, status)
    ride = model%out
    ride%start_angle = start%angle
    ride%rhs_evaluations = int(result%stats%rhs_evaluations)
    if (.not. status%ok()) return
    if (result%outcome == DRIVE_END_TIME) then
      call set_status(status, STATUS_DOMAIN, 'cuboid ride: the slide''s end was not reached within '// &
                      format_short(options%t_end)//' s')
      return
    end if
    ride%reached_end = result%outcome == DRIVE_EVENT_STOP
    ride%duration = result%t
  end subroutine ride_cuboid

  subroutine cuboid_rhs(self, t, y, ydot, status)
    class(cuboid_model_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    ydot(1:2) = y(3:4)
    call self%mechanism%dynamics(self%work, t, y(1:2), y(3:4), ydot(3:4), status)
  end subroutine cuboid_rhs

  integer function cuboid_root_count(self) result(n)
    class(cuboid_model_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 1
  end function cuboid_root_count

  !> The end of the slide.
  subroutine cuboid_roots(self, t, y, g)
    class(cuboid_model_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    associate (unused => t)
    end associate
    g(1) = self%u_end - y(1)
  end subroutine cuboid_roots

  !> Evaluates the state and keeps the maxima (default handle_event: every
  !> event, i.e. the end, stops the ride).
  subroutine cuboid_record(self, t, y, kind, status)
    class(cuboid_model_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    real(wp) :: qdd(2), a, lever, pressing, rho(3), ac(3), f(3), m(3), theta(3, 3), rot(3, 3)
    associate (unused => kind)
    end associate
    ! the frames' motion at (t, y): q'' from the dynamics, then the velocity
    ! and acceleration passes (the mechanism's evaluate would add the inverse
    ! dynamics and the normal forces, which the cuboid does not need)
    call self%mechanism%dynamics(self%work, t, y(1:2), y(3:4), qdd, status)
    if (.not. status%ok()) return
    call self%mechanism%set_velocities(self%work, y(3:4))
    call self%mechanism%set_accelerations(self%work, qdd)
    associate (fr => self%work%frames(self%frame), b => self%body)
      rot = fr%rot
      if (self%kind == ACCELERATION_FELT) then
        a = norm2(fr%a - b%gravity)
      else
        a = norm2(fr%a)
      end if
      rho = b%com_height*rot(:, 3)
      ac = fr%a + cross(fr%alpha, rho) + cross(fr%omega, cross(fr%omega, rho))
      theta = matmul(rot, matmul(self%inertia, transpose(rot)))
      f = b%mass*(ac - b%gravity)
      m = matmul(theta, fr%alpha) + cross(fr%omega, matmul(theta, fr%omega)) + cross(rho, f)
      lever = tipping_lever_arm(f, m, rot(:, 2), rot(:, 3))
      pressing = dot_product(f, rot(:, 3))
      self%out%min_normal_force = min(self%out%min_normal_force, pressing)
      self%out%lifts_off = self%out%lifts_off .or. .not. pressing > 0
      call take_sample(self%excess, t, &
        (abs(dot_product(m, rot(:, 2))) - self%lever_limit*pressing)/(b%mass*norm2(b%gravity)))
      if (self%keep) call keep_sample(self%out%series, t, y, fr%r, fr%v, a, lever, pressing)
      self%out%end_speed = norm2(fr%v)
    end associate
    if (a > self%acceleration%value) self%out%u_of_max = y(1)
    call take_sample(self%acceleration, t, a)
    call take_sample(self%lever, t, abs(lever))
    self%out%max_acceleration = self%acceleration%value
    self%out%time_of_max = self%acceleration%time
    self%out%max_lever_arm = self%lever%value
    self%out%time_of_max_lever = self%lever%time
    self%out%max_tipping_excess = self%excess%value
  end subroutine cuboid_record

  !> Takes the sample (t, x) into the running maximum m.
  pure subroutine take_sample(m, t, x)
    type(running_max_t), intent(inout) :: m
    real(wp), intent(in) :: t, x
    real(wp) :: d1, d2, h1, h2, c1, c2, tm, xm
    if (m%refine_next) then   ! the sample after the best one: the parabola through the three
      m%refine_next = .false.
      h1 = m%best_time(2) - m%best_time(1)
      h2 = t - m%best_time(2)
      if (h1 > 0 .and. h2 > 0 .and. max(abs(m%best(1)), abs(m%best(2)), abs(x)) < sqrt(huge(x))) then
        d1 = (m%best(2) - m%best(1))/h1
        d2 = (x - m%best(2))/h2
        c2 = (d2 - d1)/(h1 + h2)      ! x(s) = x2 + c1 (s - t2) + c2 (s - t2)^2
        c1 = d1 + c2*h1
        if (c2 < 0) then
          tm = m%best_time(2) - c1/(2*c2)
          if (tm > m%best_time(1) .and. tm < t) then
            xm = m%best(2) - c1**2/(4*c2)
            if (xm > m%value) then
              m%value = xm
              m%time = tm
            end if
          end if
        end if
      end if
    end if
    if (x > m%value) then
      m%value = x
      m%time = t
      m%best = [m%last, x]
      m%best_time = [m%last_time, t]
      m%refine_next = m%have_last
    end if
    m%last = x
    m%last_time = t
    m%have_last = .true.
  end subroutine take_sample

  subroutine keep_sample(s, t, y, r, v, a, lever, pressing)
    type(cuboid_series_t), intent(inout) :: s
    real(wp), intent(in) :: t, y(:), r(3), v(3), a, lever, pressing
    integer :: cap
    if (.not. allocated(s%time)) then
      cap = 1024
      allocate (s%time(cap), s%u(cap), s%v(cap), s%position(3, cap), s%acceleration(cap), &
                s%lever_arm(cap), s%speed(cap), s%normal_force(cap))
    end if
    if (s%n == size(s%time)) then
      s%time = [s%time, s%time]
      s%u = [s%u, s%u]
      s%v = [s%v, s%v]
      s%position = reshape([s%position, s%position], [3, 2*s%n])
      s%acceleration = [s%acceleration, s%acceleration]
      s%lever_arm = [s%lever_arm, s%lever_arm]
      s%speed = [s%speed, s%speed]
      s%normal_force = [s%normal_force, s%normal_force]
    end if
    s%n = s%n + 1
    s%time(s%n) = t
    s%u(s%n) = y(1)
    s%v(s%n) = y(2)
    s%position(:, s%n) = r
    s%acceleration(s%n) = a
    s%lever_arm(s%n) = lever
    s%speed(s%n) = norm2(v)
    s%normal_force(s%n) = pressing
  end subroutine keep_sample
end module design_cuboid_ride

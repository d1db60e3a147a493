!> The impact law: the impulse at a point contact that closes with an
!> approaching normal speed (flight and landing, issue 25).
!>
!> The bodies' inertia enters only through the Delassus matrix K (m/s per
!> N s): an impulse L on body 1 at the contact point (-L on body 2) changes
!> the relative velocity of the two contact points by K L. For a free rigid
!> body K = E/m + skew(r)^T I^-1 skew(r) (rigid_body_delassus, r from the
!> centre of mass to the contact point, I in world axes); for two bodies the
!> sum of both; for a mechanism J M^-1 J^T. So the effective mass at the
!> contact, not the body mass, sets the impulse.
!>
!> The impact is resolved in the normal impulse p as its clock (Darboux-Keller,
!> Stronge 2000, "Impact mechanics", ch. 5): the relative velocity v(p) obeys
!>   dv/dp = K (n + f_t),   f_t = -mu v_t/|v_t| while the points slip,
!>   f_t = lambda (tangential, |lambda| <= mu) that keeps v_t = 0 while they stick,
!> with Coulomb's mu during the impact. Slip may stop (stick, or slip again in
!> the direction K's coupling forces) and change direction on the way.
!> Compression ends at v_n = 0 with the normal impulse's work W_c < 0; the
!> impact ends when the restitution phase has given back e^2 |W_c| (the
!> energetic coefficient of restitution e in [0, 1]). Decision (docs/contact.md):
!> the energetic coefficient rather than Newton's v_n+ = -e v_n-, because
!> Newton's, with friction and a normal-tangential coupling in K, can create
!> energy (Kane and Levinson's rod); the two agree whenever slip neither stops
!> nor turns during the impact (always on a sphere or without friction:
!> v_n+ = -e v_n- exactly then). The energy the impact removes is
!> -(L . (v- + v+))/2 >= 0.
!>
!> Phases with a constant f_t (sticking, or slip in a fixed direction) are
!> linear in p and done in closed form; slip that turns is integrated by
!> classical Runge-Kutta in p (2000 steps across the impact's scale), each
!> phase's end located inside its step.
module kinetostatics_impact
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_vector, only: cross, skew, unit_vector
  use base_text, only: format_short, format_integer
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN, STATUS_INTERNAL
  implicit none (type, external)
  private
  public :: impact_law_t, impact_outcome_t, resolve_impact, rigid_body_delassus, tangent_basis

  !> Restitution e (energetic, 1) and Coulomb mu (1) during an impact.
  type :: impact_law_t
    real(wp) :: restitution = 0
    real(wp) :: mu = 0
  end type impact_law_t

  type :: impact_outcome_t
    logical :: approaching = .false.       !< false: v_n >= 0, no impulse
    real(wp) :: impulse(3) = 0             !< N s, on body 1 (world axes)
    real(wp) :: normal_impulse = 0         !< N s, n . impulse
    real(wp) :: velocity_after(3) = 0      !< m/s, relative contact velocity after
    real(wp) :: normal_speed_before = 0    !< m/s, n . v- (< 0: approaching)
    real(wp) :: normal_speed_after = 0     !< m/s, n . v+
    real(wp) :: energy_lost = 0            !< J, -(L . (v- + v+))/2
    logical :: sticks_at_end = .false.     !< the points stick when the impact ends
    integer :: slip_stops = 0              !< how often slip stopped during the impact
  end type impact_outcome_t

  integer, parameter :: steps_per_scale = 2000   ! Runge-Kutta steps across the frictionless impulse
  integer, parameter :: max_scales = 100         ! steps allowed: this many times steps_per_scale
  integer, parameter :: max_phases = 64
  integer, parameter :: direction_samples = 720  ! angles searched for slip from rest
  integer, parameter :: END_COMPRESSION = 1, END_IMPACT = 2, END_SLIP = 3
  ! With K positive definite every phase ends (slip that pushes the points
  ! together always stops first); not finding an end is a bug.
  character(len=*), parameter :: no_end_message = 'impact: no end of the impact found (the normal speed '// &
    'does not grow with the normal impulse)'

  !> The impact's state along p: relative velocity and the normal impulse's work.
  type :: impact_track_t
    real(wp) :: p = 0, v(3) = 0, work = 0
  end type impact_track_t

  !> One impact being resolved: the law, K, the contact axes and the track.
  type :: impact_walk_t
    type(impact_law_t) :: law
    real(wp) :: k(3, 3) = 0, n(3) = 0, t1(3) = 0, t2(3) = 0
    real(wp) :: p_scale = 0, v_tol = 0, settle_speed = 0
    type(impact_track_t) :: track
    logical :: compressing = .true., done = .false.
    real(wp) :: target = 0
    integer :: slip_stops = 0
  end type impact_walk_t

contains

  !> K of a free rigid body: mass (kg), inertia about its centre of mass in
  !> world axes (kg m^2), arm r from the centre of mass to the contact point (m).
  pure function rigid_body_delassus(mass, inertia, arm) result(k)
    real(wp), intent(in) :: mass, inertia(3, 3), arm(3)
    real(wp) :: k(3, 3)
    real(wp) :: s(3, 3), inv(3, 3)
    integer :: i
    s = skew(arm)
    inv = inverse3(inertia)
    k = matmul(transpose(s), matmul(inv, s))
    do i = 1, 3
      k(i, i) = k(i, i) + 1/mass
    end do
  end function rigid_body_delassus

  !> The impulse of an impact with relative contact velocity v_before (body 1's
  !> point relative to body 2's) and unit normal n (pointing from body 2 to
  !> body 1: separation is n . v > 0); K symmetric positive definite.
  subroutine resolve_impact(law, k, normal, v_before, outcome, status)
    type(impact_law_t), intent(in) :: law
    real(wp), intent(in) :: k(3, 3), normal(3), v_before(3)
    type(impact_outcome_t), intent(out) :: outcome
    type(status_t), intent(inout) :: status
    type(impact_walk_t) :: walk
    integer :: phase

    if (.not. (law%restitution >= 0 .and. law%restitution <= 1)) then
      call set_status(status, STATUS_INVALID_INPUT, 'impact: restitution '//format_short(law%restitution)// &
        ' outside [0, 1]')
      return
    end if
    if (.not. (law%mu >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'impact: mu '//format_short(law%mu)//' must be >= 0')
      return
    end if
    if (.not. (norm2(normal) > 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'impact: the contact normal is zero')
      return
    end if
    walk%law = law
    walk%k = k
    walk%n = normal/norm2(normal)
    call tangent_basis(walk%n, walk%t1, walk%t2)
    outcome%normal_speed_before = dot_product(walk%n, v_before)
    outcome%velocity_after = v_before
    outcome%normal_speed_after = outcome%normal_speed_before
    if (.not. (outcome%normal_speed_before < 0)) return
    outcome%approaching = .true.
    if (.not. symmetric_positive_definite(k)) then
      call set_status(status, STATUS_INVALID_INPUT, 'impact: the Delassus matrix K is not symmetric positive definite')
      return
    end if

    walk%v_tol = 64*epsilon(1.0_wp)*norm2(v_before)
    walk%settle_speed = 1e-9_wp*norm2(v_before)
    ! The frictionless impulse sets the scale of p (exact without coupling).
    walk%p_scale = (1 + law%restitution)*abs(outcome%normal_speed_before)/dot_product(walk%n, matmul(k, walk%n))
    walk%track%v = v_before
    do phase = 1, max_phases
      call advance_phase(walk, status)
      if (.not. status%ok() .or. walk%done) exit
    end do
    if (.not. status%ok()) return
    if (.not. walk%done) then
      call set_status(status, STATUS_DOMAIN, 'impact: slip stopped and started again more than '// &
        format_integer(max_phases)//' times')
      return
    end if
    outcome%impulse = matmul(inverse3(k), walk%track%v - v_before)
    outcome%normal_impulse = walk%track%p
    outcome%velocity_after = walk%track%v
    outcome%normal_speed_after = dot_product(walk%n, walk%track%v)
    outcome%sticks_at_end = law%mu > 0 .and. tangential_speed(walk%track%v, walk%n) <= walk%v_tol
    outcome%slip_stops = walk%slip_stops
    outcome%energy_lost = -0.5_wp*dot_product(outcome%impulse, v_before + walk%track%v)
  end subroutine resolve_impact

  !> One phase of constant character (stick, slip in a fixed direction, or
  !> turning slip) until the impact ends or slip stops.
  subroutine advance_phase(walk, status)
    type(impact_walk_t), intent(inout) :: walk
    type(status_t), intent(inout) :: status
    real(wp) :: lambda(3), direction(3), p_stop, rate
    logical :: reached
    associate (k => walk%k, n => walk%n, mu => walk%law%mu)
      if (mu == 0) then
        ! Frictionless: v = v- + K n p throughout.
        call linear_to_end(walk, matmul(k, n), huge(1.0_wp), reached, status)
        return
      end if
      if (tangential_speed(walk%track%v, n) <= walk%v_tol) then
        ! At rest tangentially: stick if the cone holds the sticking impulse,
        ! else slip starts in the direction the coupling drives it; that
        ! direction is a fixed one, so the slip stays straight.
        walk%track%v = dot_product(n, walk%track%v)*n
        call sticking_ratio(k, n, walk%t1, walk%t2, lambda)
        if (norm2(lambda) <= mu) then
          call linear_to_end(walk, matmul(k, n + lambda), huge(1.0_wp), reached, status)
        else
          call slip_start_direction(k, n, walk%t1, walk%t2, mu, direction, status)
          if (.not. status%ok()) return
          call linear_to_end(walk, matmul(k, n - mu*direction), huge(1.0_wp), reached, status)
        end if
        return
      end if
      direction = unit_vector(walk%track%v - dot_product(n, walk%track%v)*n)
      if (.not. is_fixed_direction(k, n, mu, direction)) then
        call curved_slip_phase(walk, status)
        return
      end if
      ! Slip in a fixed direction: linear until v_t reaches zero.
      rate = dot_product(direction, matmul(k, n - mu*direction))
      p_stop = huge(1.0_wp)
      if (rate < 0) p_stop = walk%track%p - dot_product(direction, walk%track%v)/rate
      call linear_to_end(walk, matmul(k, n - mu*direction), p_stop, reached, status)
      if (reached .and. .not. walk%done) call stop_slip(walk)
    end associate
  end subroutine advance_phase

  !> Along v = v0 + slope (p - p0) up to p_limit: ends the compression where
  !> v_n = 0 (its work sets the target (1 - e^2) W_c) and the impact where the
  !> work reaches the target; else moves to p_limit (reached). A phase that
  !> can end neither way without a limit cannot happen with K positive definite.
  subroutine linear_to_end(walk, slope, p_limit, reached, status)
    type(impact_walk_t), intent(inout) :: walk
    real(wp), intent(in) :: slope(3), p_limit
    logical, intent(out) :: reached
    type(status_t), intent(inout) :: status
    real(wp) :: vn, s, dp, rest, disc
    reached = .false.
    s = dot_product(walk%n, slope)
    vn = dot_product(walk%n, walk%track%v)
    if (walk%compressing) then
      dp = huge(1.0_wp)
      if (s > 0) dp = -vn/s
      if (dp > p_limit - walk%track%p) then
        call move_to_limit()
        return
      end if
      call move(dp)
      call finish_compression(walk)
      if (walk%done) return
      vn = dot_product(walk%n, walk%track%v)
    end if
    ! Restitution: the work W(p) = W0 + vn dp + s dp^2/2 rises to the target.
    rest = walk%target - walk%track%work
    if (rest <= 0) then
      walk%done = .true.
      return
    end if
    disc = vn**2 + 2*s*rest
    dp = huge(1.0_wp)
    if (disc >= 0 .and. (vn > 0 .or. s > 0)) dp = 2*rest/(vn + sqrt(disc))
    if (dp > p_limit - walk%track%p) then
      call move_to_limit()
      return
    end if
    call move(dp)
    walk%done = .true.
  contains
    subroutine move(step)
      real(wp), intent(in) :: step
      walk%track%work = walk%track%work + dot_product(walk%n, walk%track%v)*step + s*step**2/2
      walk%track%v = walk%track%v + slope*step
      walk%track%p = walk%track%p + step
    end subroutine move

    subroutine move_to_limit()
      if (p_limit == huge(1.0_wp)) then
        call set_status(status, STATUS_INTERNAL, no_end_message)
        return
      end if
      call move(p_limit - walk%track%p)
      reached = .true.
    end subroutine move_to_limit
  end subroutine linear_to_end

  !> The compression ends here (v_n = 0): the restitution's target work.
  subroutine finish_compression(walk)
    type(impact_walk_t), intent(inout) :: walk
    walk%compressing = .false.
    walk%target = (1 - walk%law%restitution**2)*walk%track%work
    walk%done = walk%track%work >= walk%target
  end subroutine finish_compression

  !> Slip whose direction turns (K drives v_t across its direction): classical
  !> Runge-Kutta in p, the compression's and the impact's ends located in their
  !> step by bisection of the step length. Near rest the direction turns at a
  !> rate ~ 1/|v_t|: steps shrink to a tenth of the distance to rest, and the
  !> last stretch (|v_t| below settle_speed) is straight, as the direction has
  !> settled by then (its error times that stretch's impulse is below rounding).
  subroutine curved_slip_phase(walk, status)
    type(impact_walk_t), intent(inout) :: walk
    type(status_t), intent(inout) :: status
    real(wp) :: h, hit, first_hit, speed, drive(3), u(3), rate
    type(impact_track_t) :: next
    integer :: step, which, first
    logical :: reached_rest
    associate (k => walk%k, n => walk%n, mu => walk%law%mu)
      do step = 1, max_scales*steps_per_scale
        speed = tangential_speed(walk%track%v, n)
        u = unit_vector(walk%track%v - dot_product(n, walk%track%v)*n)
        drive = matmul(k, n - mu*u)
        rate = dot_product(u, drive)
        if (speed <= walk%settle_speed .and. rate < 0) then
          call linear_to_end(walk, drive, walk%track%p + speed/(-rate), reached_rest, status)
          if (reached_rest .and. .not. walk%done) call stop_slip(walk)
          return
        end if
        h = min(walk%p_scale/steps_per_scale, 0.1_wp*speed/norm2(drive - dot_product(n, drive)*n))
        call rk4_step(walk, walk%track, h, next)
        first = 0
        first_hit = huge(1.0_wp)
        do which = END_COMPRESSION, END_SLIP
          if (.not. reached(walk, which, walk%track, next)) cycle
          hit = locate(walk, which, h)
          if (hit < first_hit) then
            first = which
            first_hit = hit
          end if
        end do
        if (first == 0) then
          walk%track = next
          cycle
        end if
        call rk4_step(walk, walk%track, first_hit, next)
        walk%track = next
        select case (first)
        case (END_COMPRESSION)
          call finish_compression(walk)
          if (walk%done) return
        case (END_IMPACT)
          walk%done = .true.
          return
        case (END_SLIP)
          call stop_slip(walk)
          return
        end select
      end do
    end associate
    call set_status(status, STATUS_INTERNAL, no_end_message)
  end subroutine curved_slip_phase

  !> Slip has stopped: what is left of v_t (below settle_speed) is taken out by
  !> the tangential impulse K_tt^-1 (-v_t), so that v stays v- + K L.
  subroutine stop_slip(walk)
    type(impact_walk_t), intent(inout) :: walk
    real(wp) :: rest(3)
    associate (k => walk%k, n => walk%n)
      walk%slip_stops = walk%slip_stops + 1
      rest = tangential_solve(k, walk%t1, walk%t2, -walk%track%v)
      walk%track%v = walk%track%v + matmul(k, rest)
      walk%track%v = dot_product(n, walk%track%v)*n
    end associate
  end subroutine stop_slip

  !> Whether end `which` lies between tracks a and b (b one step after a):
  !> the compression's (v_n >= 0), the impact's (work >= target), or slip's
  !> (v_t turned against its direction at a, or vanished).
  logical function reached(walk, which, a, b)
    type(impact_walk_t), intent(in) :: walk
    integer, intent(in) :: which
    type(impact_track_t), intent(in) :: a, b
    associate (n => walk%n)
      select case (which)
      case (END_COMPRESSION)
        reached = walk%compressing .and. dot_product(n, b%v) >= 0
      case (END_IMPACT)
        reached = .not. walk%compressing .and. b%work >= walk%target
      case default
        reached = dot_product(b%v - dot_product(n, b%v)*n, a%v - dot_product(n, a%v)*n) <= 0 .or. &
          tangential_speed(b%v, n) <= walk%v_tol
      end select
    end associate
  end function reached

  !> The shortest step from walk%track that reaches end `which` (bisection).
  real(wp) function locate(walk, which, h) result(hi)
    type(impact_walk_t), intent(in) :: walk
    integer, intent(in) :: which
    real(wp), intent(in) :: h
    real(wp) :: lo, mid
    type(impact_track_t) :: trial
    integer :: it
    lo = 0
    hi = h
    do it = 1, 200
      mid = (lo + hi)/2
      if (mid <= lo .or. mid >= hi) exit
      call rk4_step(walk, walk%track, mid, trial)
      if (reached(walk, which, walk%track, trial)) then
        hi = mid
      else
        lo = mid
      end if
    end do
  end function locate

  !> One classical Runge-Kutta step of length dp in the slip equations.
  subroutine rk4_step(walk, a, dp, b)
    type(impact_walk_t), intent(in) :: walk
    type(impact_track_t), intent(in) :: a
    real(wp), intent(in) :: dp
    type(impact_track_t), intent(out) :: b
    real(wp) :: k1(3), k2(3), k3(3), k4(3), w1, w2, w3, w4
    call slip_rate(a%v, k1, w1)
    call slip_rate(a%v + dp/2*k1, k2, w2)
    call slip_rate(a%v + dp/2*k2, k3, w3)
    call slip_rate(a%v + dp*k3, k4, w4)
    b%v = a%v + dp/6*(k1 + 2*k2 + 2*k3 + k4)
    b%work = a%work + dp/6*(w1 + 2*w2 + 2*w3 + w4)
    b%p = a%p + dp
  contains
    subroutine slip_rate(v, dv, dw)
      real(wp), intent(in) :: v(3)
      real(wp), intent(out) :: dv(3), dw
      dv = matmul(walk%k, walk%n - walk%law%mu*unit_vector(v - dot_product(walk%n, v)*walk%n))
      dw = dot_product(walk%n, v)
    end subroutine slip_rate
  end subroutine rk4_step

  !> The tangential impulse per unit normal impulse that keeps v_t = 0:
  !> lambda = -K_tt^-1 K_tn (in world axes, in the tangent plane).
  subroutine sticking_ratio(k, n, t1, t2, lambda)
    real(wp), intent(in) :: k(3, 3), n(3), t1(3), t2(3)
    real(wp), intent(out) :: lambda(3)
    lambda = tangential_solve(k, t1, t2, -matmul(k, n))
  end subroutine sticking_ratio

  !> The tangential x (in the plane of t1, t2) with P_t K x = P_t b: K's
  !> tangential block solved by Cramer's rule (symmetric positive definite).
  pure function tangential_solve(k, t1, t2, b) result(x)
    real(wp), intent(in) :: k(3, 3), t1(3), t2(3), b(3)
    real(wp) :: x(3)
    real(wp) :: a11, a12, a22, b1, b2, det
    a11 = dot_product(t1, matmul(k, t1))
    a12 = dot_product(t1, matmul(k, t2))
    a22 = dot_product(t2, matmul(k, t2))
    b1 = dot_product(t1, b)
    b2 = dot_product(t2, b)
    det = a11*a22 - a12**2
    x = ((a22*b1 - a12*b2)/det)*t1 + ((a11*b2 - a12*b1)/det)*t2
  end function tangential_solve

  !> Slip from rest where sticking needs more than mu: the direction u in the
  !> tangent plane along which K (n - mu u) drives v_t, i.e.
  !> P_t K (n - mu u) = alpha u with alpha > 0 (the first such u by angle).
  subroutine slip_start_direction(k, n, t1, t2, mu, direction, status)
    real(wp), intent(in) :: k(3, 3), n(3), t1(3), t2(3), mu
    real(wp), intent(out) :: direction(3)
    type(status_t), intent(inout) :: status
    real(wp) :: a, b, fa, fb, m, fm, best
    integer :: i, it
    logical :: found
    found = .false.
    best = -huge(1.0_wp)
    direction = 0
    do i = 0, direction_samples - 1
      a = two_pi*i/direction_samples
      b = two_pi*(i + 1)/direction_samples
      fa = turn(a)
      fb = turn(b)
      if (fa == 0 .or. fa*fb < 0) then
        do it = 1, 200
          if (fa == 0) exit
          m = (a + b)/2
          fm = turn(m)
          if (fm == 0 .or. b - a <= 4*epsilon(1.0_wp)) then
            a = m
            exit
          end if
          if (fa*fm < 0) then
            b = m
          else
            a = m
            fa = fm
          end if
        end do
        if (drive(a) > best) then
          best = drive(a)
          direction = cos(a)*t1 + sin(a)*t2
          found = best > 0
        end if
      end if
    end do
    if (.not. found) call set_status(status, STATUS_DOMAIN, 'impact: no slip direction from rest')
  contains
    !> The tangential drive's component across u (zero where it points along u).
    real(wp) function turn(angle)
      real(wp), intent(in) :: angle
      real(wp) :: u(3), d(3)
      u = cos(angle)*t1 + sin(angle)*t2
      d = matmul(k, n - mu*u)
      turn = dot_product(cross(u, d), n)
    end function turn
    real(wp) function drive(angle)
      real(wp), intent(in) :: angle
      real(wp) :: u(3)
      u = cos(angle)*t1 + sin(angle)*t2
      drive = dot_product(u, matmul(k, n - mu*u))
    end function drive
  end subroutine slip_start_direction

  !> Slip keeps its direction u when K (n - mu u) has no tangential part across u.
  logical function is_fixed_direction(k, n, mu, u)
    real(wp), intent(in) :: k(3, 3), n(3), mu, u(3)
    real(wp) :: d(3)
    d = matmul(k, n - mu*u)
    is_fixed_direction = abs(dot_product(cross(u, d), n)) <= 16*epsilon(1.0_wp)*maxval(abs(k))
  end function is_fixed_direction

  !> Symmetric to rounding, and its leading minors positive (Sylvester).
  pure logical function symmetric_positive_definite(k)
    real(wp), intent(in) :: k(3, 3)
    symmetric_positive_definite = maxval(abs(k - transpose(k))) <= 64*epsilon(1.0_wp)*maxval(abs(k)) .and. &
      k(1, 1) > 0 .and. k(1, 1)*k(2, 2) - k(1, 2)*k(2, 1) > 0 .and. &
      dot_product(k(:, 1), cross(k(:, 2), k(:, 3))) > 0
  end function symmetric_positive_definite

  pure real(wp) function tangential_speed(v, n)
    real(wp), intent(in) :: v(3), n(3)
    tangential_speed = norm2(v - dot_product(n, v)*n)
  end function tangential_speed

  pure subroutine tangent_basis(n, t1, t2)
    real(wp), intent(in) :: n(3)
    real(wp), intent(out) :: t1(3), t2(3)
    if (abs(n(1)) < 0.9_wp) then
      t1 = unit_vector(cross(n, [1.0_wp, 0.0_wp, 0.0_wp]))
    else
      t1 = unit_vector(cross(n, [0.0_wp, 1.0_wp, 0.0_wp]))
    end if
    t2 = cross(n, t1)
  end subroutine tangent_basis

  pure function inverse3(a) result(b)
    real(wp), intent(in) :: a(3, 3)
    real(wp) :: b(3, 3)
    b(:, 1) = cross(a(:, 2), a(:, 3))
    b(:, 2) = cross(a(:, 3), a(:, 1))
    b(:, 3) = cross(a(:, 1), a(:, 2))
    b = transpose(b)/dot_product(a(:, 1), b(:, 1))
  end function inverse3
end module kinetostatics_impact

!> The impact of two free rigid bodies at a point, or of one on the ground
!> (issue 25): the impulse from the impact law (kinetostatics_impact:
!> restitution e on the normal relative speed, Coulomb-limited tangential
!> impulse) with the Delassus matrix of the PAIR at the contact point,
!>   K = K_1 + K_2,  K_i = E/m_i + skew(r_i)^T I_i^-1 skew(r_i)
!> (r_i from body i's centre of mass to its contact point, I_i its inertia
!> in world axes; the ground adds nothing: it does not move), and each
!> body's twist changed by it: +L on body 2 at its point, -L on body 1 at
!> its, so that the pair's momentum is kept (to rounding) and, about any
!> point, its angular momentum (both points the same to the gap's rounding,
!> ~1e-14 m, at a located landing).
!>
!> Body 2 is the contact's body_2, body 1 its body_1 (the ground or a body);
!> n is the gap's normal, out of shape_1 towards body 2, and the relative
!> velocity is body 2's point's less body 1's: the law's body 1 is the
!> contact's body_2 (kinetostatics_impact resolve_impact: separation n.v > 0).
!> The arithmetic of a body on the ground is that of the flight's impact on
!> the ground before bodies could hit each other, to the bit.
module contact_body_impact
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use base_vector, only: cross
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t, resolve_impact, rigid_body_delassus
  use kinetostatics_point_impacts, only: resolve_impacts
  implicit none (type, external)
  private
  public :: impact_body_t, collision_t, collide, collide_at_once, close_at_once, pair_delassus, relative_velocity, &
    apply_impulse, centre_speed

  !> A free rigid body at an impact (world): its pose's origin and centre of
  !> mass, its twist (omega and the origin's velocity), mass and inertia
  !> about the centre of mass. mass 0: the ground (fixed, at rest).
  type :: impact_body_t
    real(wp) :: mass = 0                   ! kg (0: the ground)
    real(wp) :: inertia(3, 3) = 0          ! kg m^2, about the centre of mass, world axes
    real(wp) :: origin(3) = 0, centre(3) = 0   ! m, world
    real(wp) :: omega(3) = 0, velocity(3) = 0  ! rad/s; m/s of the origin
  end type impact_body_t

  !> What an impact did (collide).
  type :: collision_t
    type(impact_outcome_t) :: outcome      ! the impact law's (resolve_impact)
    real(wp) :: impulse(3) = 0             ! N s, on body 2 (-impulse on body 1), the closing's included
    real(wp) :: velocity_after(3) = 0      ! m/s, body 2's point relative to body 1's after it all
    real(wp) :: energy_lost = 0            ! J, the impact's and the closing's
    logical :: closed = .false.            ! the rebound was below close_speed: the closing impulse was added
  end type collision_t

contains

  !> The speed of the body's centre of mass (m/s; 0 for the ground).
  pure real(wp) function centre_speed(body) result(speed)
    type(impact_body_t), intent(in) :: body
    speed = norm2(body%velocity + cross(body%omega, body%centre - body%origin))
  end function centre_speed

  !> The impact of body_2 on body_1 (the ground: mass 0) at their points
  !> point_1, point_2 with the common normal n (out of body 1), by `law`;
  !> both bodies' twists changed. A rebound below close_speed closes the
  !> contact (`closed`): closing_impulse takes away what is left of the
  !> points' normal velocity (all of their relative velocity where
  !> `rolling`), its energy added to the impact's.
  subroutine collide(law, n, point_1, point_2, body_1, body_2, close_speed, rolling, result, status)
    type(impact_law_t), intent(in) :: law
    real(wp), intent(in) :: n(3), point_1(3), point_2(3), close_speed
    type(impact_body_t), intent(inout) :: body_1, body_2
    logical, intent(in) :: rolling
    type(collision_t), intent(out) :: result
    type(status_t), intent(inout) :: status
    real(wp) :: k(3, 3), closing(3)
    k = pair_delassus(body_1, body_2, point_1, point_2)
    call resolve_impact(law, k, n, relative_velocity(body_1, body_2, point_1, point_2), result%outcome, status)
    if (.not. status%ok()) return
    associate (outcome => result%outcome)
      result%impulse = outcome%impulse
      result%velocity_after = outcome%velocity_after
      result%energy_lost = outcome%energy_lost
      result%closed = outcome%normal_speed_after < close_speed
      if (result%closed) then
        call closing_impulse(k, n, outcome%velocity_after, rolling, closing, status)
        if (.not. status%ok()) return
        result%velocity_after = outcome%velocity_after + matmul(k, closing)
        result%energy_lost = outcome%energy_lost - dot_product(closing, outcome%velocity_after + &
                                                               result%velocity_after)/2
        result%impulse = result%impulse + closing
      end if
    end associate
    call apply_impulse(body_2, point_2, result%impulse, status)
    call apply_impulse(body_1, point_1, -result%impulse, status)
  end subroutine collide

  !> K of the pair at the contact points point_1 (on body_1) and point_2
  !> (on body_2), m/s per N s.
  pure function pair_delassus(body_1, body_2, point_1, point_2) result(k)
    type(impact_body_t), intent(in) :: body_1, body_2
    real(wp), intent(in) :: point_1(3), point_2(3)
    real(wp) :: k(3, 3)
    k = rigid_body_delassus(body_2%mass, body_2%inertia, point_2 - body_2%centre)
    if (body_1%mass > 0) k = k + rigid_body_delassus(body_1%mass, body_1%inertia, point_1 - body_1%centre)
  end function pair_delassus

  !> The velocity of body_2's point point_2 relative to body_1's point_1 (m/s).
  pure function relative_velocity(body_1, body_2, point_1, point_2) result(v)
    type(impact_body_t), intent(in) :: body_1, body_2
    real(wp), intent(in) :: point_1(3), point_2(3)
    real(wp) :: v(3)
    v = body_2%velocity + cross(body_2%omega, point_2 - body_2%origin)
    if (body_1%mass > 0) v = v - (body_1%velocity + cross(body_1%omega, point_1 - body_1%origin))
  end function relative_velocity

  !> The velocity of contact i's point on its body 2 relative to its point
  !> on its body 1 (m/s), the bodies `set_of` (0: the ground), contact i
  !> between set_of(pair(1, i)) and set_of(pair(2, i)) at points_1(:, i),
  !> points_2(:, i).
  pure function contact_velocity(set_of, pair, points_1, points_2, i) result(v)
    type(impact_body_t), intent(in) :: set_of(0:)
    integer, intent(in) :: pair(:, :), i
    real(wp), intent(in) :: points_1(:, :), points_2(:, :)
    real(wp) :: v(3)
    v = relative_velocity(set_of(pair(1, i)), set_of(pair(2, i)), points_1(:, i), points_2(:, i))
  end function contact_velocity

  !> The impulse `impulse` (N s) on `body` at `point`: its centre of mass
  !> speeds up by impulse/m, its angular velocity by I^-1 (arm x impulse);
  !> its twist becomes the new one (the origin's velocity from the centre's).
  !> The ground (mass 0) is left as it is.
  subroutine apply_impulse(body, point, impulse, status)
    type(impact_body_t), intent(inout) :: body
    real(wp), intent(in) :: point(3), impulse(3)
    type(status_t), intent(inout) :: status
    real(wp) :: factored(3, 3), spin_change(3), v_centre(3)
    integer :: ipiv(3)
    if (.not. body%mass > 0) return
    factored = body%inertia
    spin_change = cross(point - body%centre, impulse)
    call lu_factor(factored, ipiv, status)
    if (status%ok()) call lu_solve(factored, ipiv, spin_change, status)
    if (.not. status%ok()) return
    v_centre = body%velocity + cross(body%omega, body%centre - body%origin) + impulse/body%mass
    body%omega = body%omega + spin_change
    body%velocity = v_centre - cross(body%omega, body%centre - body%origin)
  end subroutine apply_impulse

  !> An impact at several contacts at once (a body landing on two surfaces
  !> in one instant, three balls meeting), Newton's restitution at each.
  !> Frictionless (every mu 0): the normal impulses P >= 0 with the normal
  !> speeds after v+ = v- + W P, and at each contact either P_i = 0 and
  !> v+_i >= -e_i v-_i, or v+_i = -e_i v-_i (a linear complementarity
  !> problem; W, the Delassus matrix of the normal directions, is found
  !> column by column from each body's response to a unit impulse, and is
  !> positive definite where the contacts' normals are independent on the
  !> bodies, so the solution is one: found among the sets of active
  !> contacts). With friction at any contact: kinetostatics_point_impacts
  !> resolve_impacts (the same law with Coulomb's friction on the velocities
  !> after), with the full W of the contacts (3 x 3 blocks, world axes) from
  !> the bodies' responses at rest to unit impulses along x, y, z. Contact i
  !> is between bodies(pair(1, i)) and bodies(pair(2, i)) (index 0: the
  !> ground) at points_1(:, i), points_2(:, i) with normal normals(:, i) out
  !> of body 1; every body's twist is changed. Per contact: the normal
  !> impulse P_i, the tangential impulse's size, v-_i, v+_i and the energy it
  !> took, -P_i.(v-_i + v+_i)/2 (their sum the kinetic energy's fall);
  !> `tangent`, if present, the tangential impulses (3 x contacts, N s).
  !> The contacts `no_slip` marks, if present (rolling contacts that carry
  !> a body through the impact), hold their whole relative velocity at zero
  !> while they push, no cone (resolve_impacts' no-slip rows; their mu
  !> unused): the friction's way then, whatever the mu.
  subroutine collide_at_once(restitution, mu, normals, points_1, points_2, pair, bodies, impulse, tangential, &
                             speed_before, speed_after, energy_lost, status, tangent, no_slip)
    real(wp), intent(in) :: restitution(:), mu(:), normals(:, :), points_1(:, :), points_2(:, :)
    integer, intent(in) :: pair(:, :)
    type(impact_body_t), intent(inout) :: bodies(0:)
    real(wp), intent(out) :: impulse(:), tangential(:), speed_before(:), speed_after(:), energy_lost(:)
    type(status_t), intent(inout) :: status
    real(wp), intent(out), optional :: tangent(:, :)
    logical, intent(in), optional :: no_slip(:)
    type(impact_body_t) :: pushed(0:ubound(bodies, 1))
    real(wp) :: w(size(restitution), size(restitution))
    real(wp), allocatable :: a(:, :), rhs(:)
    integer :: i, j, m, set
    integer, allocatable :: active(:), ipiv(:)
    logical :: found
    type(status_t) :: solved
    m = size(restitution)
    tangential = 0
    if (present(tangent)) tangent = 0
    if (any(mu > 0)) then
      call with_friction()
      return
    end if
    if (present(no_slip)) then
      if (any(no_slip)) then
        call with_friction()
        return
      end if
    end if
    speed_before = [(normal_speed(bodies, i), i = 1, m)]
    do j = 1, m
      pushed = bodies
      call push(pushed, j, normals(:, j), status)
      w(:, j) = [(normal_speed(pushed, i), i = 1, m)] - speed_before
    end do
    if (.not. status%ok()) return
    found = .false.
    do set = 1, 2**m - 1
      active = pack([(i, i = 1, m)], [(btest(set, i - 1), i = 1, m)])
      a = w(active, active)
      rhs = -(1 + restitution(active))*speed_before(active)
      allocate (ipiv(size(active)))
      solved = status_t()
      call lu_factor(a, ipiv, solved)
      if (solved%ok()) call lu_solve(a, ipiv, rhs, solved)
      deallocate (ipiv)
      if (.not. solved%ok()) cycle   ! these contacts' normals dependent: another set
      impulse = 0
      impulse(active) = rhs
      speed_after = speed_before + matmul(w, impulse)
      found = all(impulse >= 0) .and. all(speed_after >= -restitution*speed_before - &
                                          64*epsilon(1.0_wp)*maxval(abs(speed_before)))
      if (found) exit
    end do
    if (.not. found) then
      call set_status(status, STATUS_DOMAIN, 'impact at several contacts at once: no impulses found that keep '// &
                      'every contact from going in (its normals dependent on the bodies)')
      return
    end if
    do j = 1, m
      call push(bodies, j, impulse(j)*normals(:, j), status)
    end do
    if (.not. status%ok()) return
    speed_after = [(normal_speed(bodies, i), i = 1, m)]
    energy_lost = -impulse*(speed_before + speed_after)/2
  contains
    !> The law with friction on the full W of the contacts.
    subroutine with_friction()
      real(wp) :: full(3*m, 3*m), v_before(3, m), v_after(3, m), p(3, m)
      integer :: k, b
      v_before = reshape([(relative(bodies, i), i = 1, m)], [3, m])
      do j = 1, m
        do k = 1, 3
          pushed = bodies
          do b = 0, ubound(bodies, 1)   ! at rest: W exactly, not a difference of speeds
            pushed(b)%omega = 0
            pushed(b)%velocity = 0
          end do
          call push(pushed, j, merge(1.0_wp, 0.0_wp, [1, 2, 3] == k), status)
          full(:, 3*j - 3 + k) = [(relative(pushed, i), i = 1, m)]
        end do
      end do
      if (.not. status%ok()) return
      full = (full + transpose(full))/2
      call resolve_impacts(full, normals, v_before, restitution, mu, p, v_after, energy_lost, status, no_slip)
      if (.not. status%ok()) return
      do j = 1, m
        call push(bodies, j, p(:, j), status)
      end do
      if (.not. status%ok()) return
      speed_before = [(dot_product(normals(:, i), v_before(:, i)), i = 1, m)]
      speed_after = [(normal_speed(bodies, i), i = 1, m)]
      impulse = [(dot_product(normals(:, i), p(:, i)), i = 1, m)]
      tangential = [(norm2(p(:, i) - impulse(i)*normals(:, i)), i = 1, m)]
      if (present(tangent)) tangent = p - spread(impulse, 1, 3)*normals
    end subroutine with_friction

    !> The relative velocity of contact i (contact_velocity).
    function relative(set_of, i) result(v)
      type(impact_body_t), intent(in) :: set_of(0:)
      integer, intent(in) :: i
      real(wp) :: v(3)
      v = contact_velocity(set_of, pair, points_1, points_2, i)
    end function relative

    !> The normal speed of contact i (body 2's point relative to body 1's).
    real(wp) function normal_speed(set_of, i) result(speed)
      type(impact_body_t), intent(in) :: set_of(0:)
      integer, intent(in) :: i
      speed = dot_product(normals(:, i), relative(set_of, i))
    end function normal_speed

    !> The impulse p at contact j: +p on its body 2, -p on its body 1.
    subroutine push(set_of, j, p, st)
      type(impact_body_t), intent(inout) :: set_of(0:)
      integer, intent(in) :: j
      real(wp), intent(in) :: p(3)
      type(status_t), intent(inout) :: st
      call apply_impulse(set_of(pair(2, j)), points_2(:, j), p, st)
      call apply_impulse(set_of(pair(1, j)), points_1(:, j), -p, st)
    end subroutine push
  end subroutine collide_at_once

  !> The contacts `closing` of an impact at several contacts at once
  !> (collide_at_once's, with the bodies after it) closed together: the
  !> impulses P_S on them that take away their normal speeds v_S
  !> (frictionless, along each normal, as closing_impulse's) and, at a
  !> contact that `rolling` marks, its whole relative velocity (the
  !> no-slip contact cannot start slipping: two more rows, along two
  !> tangents), W_SS P_S = -v_S (W the Delassus matrix of those directions,
  !> each column the bodies' response at rest to a unit impulse), applied
  !> to the bodies; a plastic impulse, its energy v_S . W_SS^-1 v_S / 2 >= 0
  !> taken, -P_i . (v_i + v'_i)/2 at each contact (every contact's velocity
  !> after changes). Contact i's normal impulse is added to impulse(i),
  !> speed_after(i) becomes its new normal speed, energy_lost(i) grows;
  !> `tangent` (3 x contacts, N s), if present, gets the tangential part of
  !> the closing's impulse added. A W_SS that is singular (the closing
  !> contacts' directions dependent on the bodies) fails.
  subroutine close_at_once(closing, normals, points_1, points_2, pair, bodies, impulse, speed_after, energy_lost, &
                           status, rolling, tangent)
    logical, intent(in) :: closing(:)
    real(wp), intent(in) :: normals(:, :), points_1(:, :), points_2(:, :)
    integer, intent(in) :: pair(:, :)
    type(impact_body_t), intent(inout) :: bodies(0:)
    real(wp), intent(inout) :: impulse(:), speed_after(:), energy_lost(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: rolling(:)
    real(wp), intent(inout), optional :: tangent(:, :)
    type(impact_body_t) :: pushed(0:ubound(bodies, 1))
    real(wp), allocatable :: a(:, :), rhs(:), dirs(:, :), v_before(:, :), p(:, :)
    real(wp) :: pn(size(closing)), speed_before(size(closing))
    logical :: slides(size(closing))
    integer, allocatable :: at(:), ipiv(:)
    integer :: i, j, b, m, n
    m = size(closing)
    ! the directions whose relative speeds the closing takes away: each closing contact's normal, a rolling one's
    ! two tangents too
    allocate (dirs(3, 0), at(0))
    do i = 1, m
      if (.not. closing(i)) cycle
      dirs = reshape([dirs, normals(:, i)], [3, size(at) + 1])
      at = [at, i]
      if (.not. present(rolling)) cycle
      if (.not. rolling(i)) cycle
      dirs = reshape([dirs, tangents(normals(:, i))], [3, size(at) + 2])
      at = [at, i, i]
    end do
    n = size(at)
    v_before = reshape([(contact_velocity(bodies, pair, points_1, points_2, i), i = 1, m)], [3, m])
    allocate (a(n, n))
    rhs = [(-dot_product(dirs(:, j), v_before(:, at(j))), j = 1, n)]
    do j = 1, n
      pushed = bodies
      do b = 0, ubound(bodies, 1)   ! at rest: W exactly
        pushed(b)%omega = 0
        pushed(b)%velocity = 0
      end do
      call apply_impulse(pushed(pair(2, at(j))), points_2(:, at(j)), dirs(:, j), status)
      call apply_impulse(pushed(pair(1, at(j))), points_1(:, at(j)), -dirs(:, j), status)
      a(:, j) = [(dot_product(dirs(:, i), contact_velocity(pushed, pair, points_1, points_2, at(i))), i = 1, n)]
    end do
    if (.not. status%ok()) return
    allocate (ipiv(n))
    call lu_factor(a, ipiv, status)
    if (status%ok()) call lu_solve(a, ipiv, rhs, status)
    if (.not. status%ok()) then
      call set_status(status, STATUS_DOMAIN, 'closing several contacts at once: their normals are dependent on '// &
                      'the bodies (no impulses take away their normal speeds)')
      return
    end if
    ! each contact's impulse: its normal row's along the normal, a rolling one's tangent rows' added
    allocate (p(3, m), source=0.0_wp)
    pn = 0
    slides = .true.
    do j = 1, n
      if (j > 1) then
        if (at(j) == at(j - 1)) then
          p(:, at(j)) = p(:, at(j)) + rhs(j)*dirs(:, j)
          slides(at(j)) = .false.
          cycle
        end if
      end if
      pn(at(j)) = rhs(j)
      p(:, at(j)) = rhs(j)*dirs(:, j)
    end do
    do j = 1, m
      call apply_impulse(bodies(pair(2, j)), points_2(:, j), p(:, j), status)
      call apply_impulse(bodies(pair(1, j)), points_1(:, j), -p(:, j), status)
    end do
    if (.not. status%ok()) return
    speed_before = [(dot_product(normals(:, i), v_before(:, i)), i = 1, m)]
    speed_after = [(dot_product(normals(:, i), contact_velocity(bodies, pair, points_1, points_2, i)), i = 1, m)]
    impulse = impulse + pn
    do i = 1, m
      if (slides(i)) then
        energy_lost(i) = energy_lost(i) - pn(i)*(speed_before(i) + speed_after(i))/2
      else
        energy_lost(i) = energy_lost(i) - dot_product(p(:, i), v_before(:, i) + &
                                                      contact_velocity(bodies, pair, points_1, points_2, i))/2
        if (present(tangent)) tangent(:, i) = tangent(:, i) + p(:, i) - pn(i)*normals(:, i)
      end if
    end do
  contains
    !> Two unit tangents of the unit normal n, with n a right-handed frame.
    function tangents(n) result(t)
      real(wp), intent(in) :: n(3)
      real(wp) :: t(3, 2)
      if (abs(n(1)) < 0.6_wp) then
        t(:, 1) = cross(n, [1.0_wp, 0.0_wp, 0.0_wp])
      else
        t(:, 1) = cross(n, [0.0_wp, 1.0_wp, 0.0_wp])
      end if
      t(:, 1) = t(:, 1)/norm2(t(:, 1))
      t(:, 2) = cross(n, t(:, 1))
    end function tangents
  end subroutine close_at_once

  !> The impulse (on the body, N s) that closes a contact whose points move
  !> apart at v after the impact (relative velocity, world; K the Delassus
  !> matrix): it takes away their normal velocity n.v along n, frictionless,
  !> p = -(n.v)/(n.K n); at a rolling contact their whole relative velocity,
  !> K^-1 (-v) (the no-slip contact cannot start slipping). Either is a
  !> plastic impulse: it removes energy, -(P.(v + v'))/2 >= 0.
  subroutine closing_impulse(k, n, v, rolling, impulse, status)
    real(wp), intent(in) :: k(3, 3), n(3), v(3)
    logical, intent(in) :: rolling
    real(wp), intent(out) :: impulse(3)
    type(status_t), intent(inout) :: status
    real(wp) :: factored(3, 3)
    integer :: ipiv(3)
    if (rolling) then
      factored = k
      impulse = -v
      call lu_factor(factored, ipiv, status)
      if (status%ok()) call lu_solve(factored, ipiv, impulse, status)
    else
      impulse = -dot_product(n, v)/dot_product(n, matmul(k, n))*n
    end if
  end subroutine closing_impulse
end module contact_body_impact

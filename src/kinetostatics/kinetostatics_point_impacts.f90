!> An impact at several points at once with Coulomb friction (issue 25): a
!> body landing flat on two contacts, a ball into a V, three balls meeting.
!>
!> The law (decision, docs/contact.md "Impacts at several points"): Newton's
!> restitution at each contact and Coulomb's friction on the velocities
!> after the impact, in one shot (Moreau's impact law with no tangential
!> restitution, as in the nonsmooth contact dynamics of Moreau and Jean).
!> With the contact points' relative velocities v- before and v+ = v- + W P
!> after (P the impulses, W the Delassus matrix of all contacts: contact i's
!> velocity change per unit impulse at contact j, 3 x 3 blocks in world
!> axes), at each contact i with normal n_i, restitution e_i, friction mu_i:
!>   - the shifted normal speed u_i = n_i.v+_i + e_i min(n_i.v-_i, 0) >= 0,
!>     the normal impulse p_i = n_i.P_i >= 0, and p_i u_i = 0;
!>   - the tangential impulse |P_t,i| <= mu_i p_i; where less, the tangential
!>     velocity after is zero (stick); else P_t,i = -mu_i p_i v+_t,i/|v+_t,i|
!>     (slip after the impact).
!> With mu = 0 this is the frictionless law of contact_body_impact
!> collide_at_once (the same linear complementarity problem). The single
!> contact's law (kinetostatics_impact) follows the impulse through the
!> impact (Darboux-Keller, energetic restitution); at several contacts that
!> needs a rule for how the contacts share the impulse on the way, so this
!> law looks only at the end. The two agree for a sphere on a plane; where
!> slip would turn during the impact they differ (a ball into a V with
!> friction: the law's friction opposes the slip after the impact).
!>
!> Solved by nonsmooth Gauss-Seidel: each contact's own problem (its 3 x 3
!> block, the others' impulses fixed) is solved exactly (no impulse, stick,
!> stick on the cone's edge to rounding, or slip in the direction found by
!> bisection in the tangent plane), sweep
!> after sweep until no impulse changes by more than sweep_tolerance of the
!> largest. Where the contacts hold one rigid body at more than one point,
!> W is singular: the bodies' velocities after are one, the split of the
!> impulses between the contacts (a squeeze along the line of two points)
!> is not fixed by rigid bodies; Gauss-Seidel gives one split that satisfies
!> the law. Newton's restitution at several contacts with friction can give
!> energy back; the energy's fall, -P.(v- + v+)/2, is checked and an impact
!> that would raise it is refused.
!>
!> A no-slip contact (a rolling contact that carries a body through the
!> impact, `no_slip`) has no cone: while it pushes it holds its whole
!> relative velocity at zero after the impact (its normal and both
!> tangential rows, W_ii P_i = -c_i with the others' impulses fixed, as a
!> rolling contact's closing in contact_body_impact close_at_once); where
!> that impulse would pull (n.P_i < 0) it opens with no impulse at all if
!> its points then move apart, and otherwise (it would have to pull, or to
!> slip, which it cannot) the impact is refused.
module kinetostatics_point_impacts
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_vector, only: cross
  use base_text, only: format_short, format_integer
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_impact, only: tangent_basis
  implicit none (type, external)
  private
  public :: resolve_impacts

  integer, parameter :: max_sweeps = 100000
  real(wp), parameter :: sweep_tolerance = 1e-14_wp   ! of the largest impulse
  integer, parameter :: slip_samples = 720             ! angles searched for a contact's slip direction
  real(wp), parameter :: edge_rounding = 16            ! a stick on the cone's edge to rounding: eps's (contact_impulse)

contains

  !> The impulses P (N s, on body 2 of each contact, world; 3 x m) of an
  !> impact at m contacts, the relative velocities after (m/s, 3 x m) and
  !> each contact's share of the energy lost, -P_i.(v-_i + v+_i)/2 (J; their
  !> sum the kinetic energy's fall). w: 3m x 3m, symmetric positive
  !> semidefinite, its diagonal blocks positive definite; normals unit.
  !> no_slip, if present, marks the no-slip contacts (their mu unused).
  subroutine resolve_impacts(w, normals, v_before, restitution, mu, impulse, v_after, energy_lost, status, no_slip)
    real(wp), intent(in) :: w(:, :), normals(:, :), v_before(:, :), restitution(:), mu(:)
    real(wp), intent(out) :: impulse(:, :), v_after(:, :), energy_lost(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: no_slip(:)
    real(wp) :: shifted(3, size(mu)), c(3), p(3), change, largest
    logical :: holds(size(mu))
    integer :: i, m, sweep
    m = size(mu)
    holds = .false.
    if (present(no_slip)) holds = no_slip
    impulse = 0
    v_after = v_before
    energy_lost = 0
    if (.not. status%ok()) return
    if (any(.not. (restitution >= 0 .and. restitution <= 1)) .or. any(.not. (mu >= 0))) then
      call set_status(status, STATUS_INVALID_INPUT, 'impact at several contacts: restitution outside [0, 1] or '// &
                      'a negative mu')
      return
    end if
    if (maxval(abs(w - transpose(w))) > 64*epsilon(1.0_wp)*maxval(abs(w))) then
      call set_status(status, STATUS_INVALID_INPUT, 'impact at several contacts: the Delassus matrix W is not '// &
                      'symmetric')
      return
    end if
    do i = 1, m
      shifted(:, i) = v_before(:, i) + restitution(i)*min(dot_product(normals(:, i), v_before(:, i)), 0.0_wp)* &
                      normals(:, i)
    end do
    do sweep = 1, max_sweeps
      change = 0
      do i = 1, m
        associate (rows => block(i))
          c = shifted(:, i) + matmul(w(rows, :), reshape(impulse, [3*m])) - matmul(w(rows, rows), impulse(:, i))
          if (holds(i)) then
            call no_slip_impulse(w(rows, rows), c, normals(:, i), p, status)
          else
            call contact_impulse(w(rows, rows), c, normals(:, i), mu(i), p, status)
          end if
        end associate
        if (.not. status%ok()) return
        change = max(change, maxval(abs(p - impulse(:, i))))
        impulse(:, i) = p
      end do
      largest = maxval(abs(impulse))
      if (change <= sweep_tolerance*largest) exit
    end do
    if (change > sweep_tolerance*largest) then
      call set_status(status, STATUS_DOMAIN, 'impact at several contacts: the impulses did not settle in '// &
                      format_integer(max_sweeps)//' sweeps (last change '//format_short(change)//' N s)')
      return
    end if
    v_after = v_before + reshape(matmul(w, reshape(impulse, [3*m])), [3, m])
    energy_lost = [(-dot_product(impulse(:, i), v_before(:, i) + v_after(:, i))/2, i = 1, m)]
    if (sum(energy_lost) < -64*epsilon(1.0_wp)*sum(abs(impulse)*(abs(v_before) + abs(v_after)))) then
      call set_status(status, STATUS_DOMAIN, 'impact at several contacts: Newton''s restitution with friction '// &
                      'would raise the kinetic energy by '//format_short(-sum(energy_lost))//' J here (a law '// &
                      'that creates energy is refused)')
    end if
  end subroutine resolve_impacts

  !> The rows of contact i in W.
  pure function block(i) result(rows)
    integer, intent(in) :: i
    integer :: rows(3)
    rows = [3*i - 2, 3*i - 1, 3*i]
  end function block

  !> One contact's impulse p (N s) where its velocity after is a p + c
  !> (a its 3 x 3 block of W, positive definite; c its velocity with the
  !> others' impulses and the restitution's shift): none where c moves it
  !> apart, else frictionless, sticking (a p + c = 0 inside the cone), or
  !> slipping: p = p_n (n - mu s) with the normal speed zero and the
  !> tangential velocity along s.
  subroutine contact_impulse(a, c, n, mu, p, status)
    real(wp), intent(in) :: a(3, 3), c(3), n(3), mu
    real(wp), intent(out) :: p(3)
    type(status_t), intent(inout) :: status
    real(wp) :: factored(3, 3), cn, t1(3), t2(3), free(3), angle0, pn, pt(3), edge(3)
    integer :: ipiv(3)
    cn = dot_product(n, c)
    p = 0
    if (cn >= 0) return
    p = -cn/dot_product(n, matmul(a, n))*n
    if (mu == 0) return
    free = matmul(a, p) + c           ! the tangential velocity without friction sets where slip is looked for
    call tangent_basis(n, t1, t2)
    angle0 = atan2(dot_product(free, t2), dot_product(free, t1))
    factored = a
    p = -c
    call lu_factor(factored, ipiv, status)
    if (status%ok()) call lu_solve(factored, ipiv, p, status)
    if (.not. status%ok()) return
    pn = dot_product(n, p)
    pt = p - pn*n
    if (pn > 0 .and. norm2(pt) <= mu*pn) return
    ! On the cone's edge stick and slip meet (the slip speed zero), and no
    ! slip direction can be found there. A sticking impulse outside the
    ! cone by no more than the velocity's rounding (its tangential part
    ! brought onto the edge changes a p + c by less than edge_rounding eps
    ! of |a| |p| + |c|, the size of the velocities' own rounding, W P and
    ! c being sums of such terms) is taken onto the edge: the law then holds
    ! exactly for the impulse and to rounding for the velocity after.
    ! Gauss-Seidel at a body held at two points leaves one contact there as
    ! a rule: it pushes the squeeze between them until one friction is full.
    if (pn > 0) then
      edge = pn*n + mu*pn*pt/norm2(pt)
      if (norm2(matmul(a, edge - p)) <= edge_rounding*epsilon(1.0_wp)*(maxval(abs(a))*norm2(p) + norm2(c))) then
        p = edge
        return
      end if
    end if
    call slip_impulse(a, c, n, t1, t2, mu, angle0, p, status)
  end subroutine contact_impulse

  !> A no-slip contact's impulse p (N s) where its velocity after is a p + c
  !> (as contact_impulse's): sticking, a p + c = 0, where that pushes (n.p
  !> >= 0, to the rounding of p); else none, where c moves it apart. A
  !> contact that would have to pull fails: it can neither stick nor slip.
  subroutine no_slip_impulse(a, c, n, p, status)
    real(wp), intent(in) :: a(3, 3), c(3), n(3)
    real(wp), intent(out) :: p(3)
    type(status_t), intent(inout) :: status
    real(wp) :: factored(3, 3)
    integer :: ipiv(3)
    factored = a
    p = -c
    call lu_factor(factored, ipiv, status)
    if (status%ok()) call lu_solve(factored, ipiv, p, status)
    if (.not. status%ok()) return
    ! a stick whose normal impulse is 0 but for rounding (a push across the contact) holds
    if (dot_product(n, p) >= -edge_rounding*epsilon(1.0_wp)*norm2(p)) return
    p = 0
    if (dot_product(n, c) >= 0) return
    call set_status(status, STATUS_DOMAIN, 'impact at several contacts: a no-slip (rolling) contact would have '// &
                    'to pull to hold, and it can neither slip nor move apart (normal speed '// &
                    format_short(dot_product(n, c))//' m/s without it)')
  end subroutine no_slip_impulse

  !> The slipping impulse: the direction s = cos(x) t1 + sin(x) t2 where
  !> the tangential velocity v_t = p_n d_t + c_t (d = a (n - mu s), p_n =
  !> -c_n/(n.d) > 0) lies along +s; the root of (s x (-c_n d_t + (n.d)
  !> c_t)).n (v_t's turn across s times n.d, without poles) nearest to angle0.
  subroutine slip_impulse(a, c, n, t1, t2, mu, angle0, p, status)
    real(wp), intent(in) :: a(3, 3), c(3), n(3), t1(3), t2(3), mu, angle0
    real(wp), intent(out) :: p(3)
    type(status_t), intent(inout) :: status
    real(wp) :: lo, hi, flo, fhi, mid, fmid, root, d(3), s(3)
    integer :: k, it, best
    best = huge(best)
    p = 0
    do k = 0, slip_samples - 1
      lo = angle0 + two_pi*(k - 0.5_wp)/slip_samples
      hi = angle0 + two_pi*(k + 0.5_wp)/slip_samples
      flo = turn(lo)
      fhi = turn(hi)
      if (flo*fhi > 0 .or. fhi == 0) cycle
      do it = 1, 200
        if (flo == 0) exit
        mid = (lo + hi)/2
        if (mid <= lo .or. mid >= hi) exit
        fmid = turn(mid)
        if (fmid == 0 .or. (fmid > 0 .eqv. flo > 0)) then
          lo = mid
          flo = fmid
        else
          hi = mid
        end if
      end do
      root = lo
      s = cos(root)*t1 + sin(root)*t2
      d = matmul(a, n - mu*s)
      if (.not. dot_product(n, d) > 0) cycle
      if (.not. dot_product(s, -dot_product(n, c)/dot_product(n, d)*d + c) > 0) cycle
      if (min(k, slip_samples - k) < best) then
        best = min(k, slip_samples - k)
        p = -dot_product(n, c)/dot_product(n, d)*(n - mu*s)
      end if
    end do
    if (best == huge(best)) call set_status(status, STATUS_DOMAIN, 'impact at several contacts: a contact '// &
      'neither sticks nor slips (no slip direction found)')
  contains
    real(wp) function turn(x)
      real(wp), intent(in) :: x
      real(wp) :: u(3), dx(3)
      u = cos(x)*t1 + sin(x)*t2
      dx = matmul(a, n - mu*u)
      turn = dot_product(cross(u, -dot_product(n, c)*dx + dot_product(n, dx)*c), n)
    end function turn
  end subroutine slip_impulse
end module kinetostatics_point_impacts

!> The impact law (kinetostatics_impact) against closed forms and an
!> independent integration:
!> - rigid_body_delassus: K L equals the contact point's velocity change of a
!>   free body given the impulse L (Newton-Euler), random bodies;
!> - a sphere on a plane: frictionless v_n+ = -e v_n-, tangential unchanged;
!>   sticking from the start (v_t+ = 0, centre speed 5/7 of v_t-); sliding
!>   throughout (L_t = mu L_n, L_n = m (1+e) |v_n|); slip that stops part way;
!> - a tilted rod, frictionless: L_n = (1+e) |v_n|/(n . K n), v_n+ = -e v_n-;
!> - random bodies, arms and velocities with friction: the impulse lies in the
!>   friction cone, K L = v+ - v-, the impact never creates energy and removes
!>   exactly (1 - e^2) of the compression's work from the normal motion where
!>   the normal and tangential motions decouple, and the result agrees with
!>   a brute-force integration of the same impact with Coulomb's law
!>   regularized (tanh of v_t/eps, many small steps, no phase logic);
!> - K not symmetric positive definite, e outside [0, 1], mu < 0 are refused;
!>   a separating contact gets no impulse.
program test_impact
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross, rot_x, rot_y, rot_z, unit_vector
  use testing, only: check, check_close, finish_tests
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t, resolve_impact, rigid_body_delassus
  implicit none (type, external)

  real(wp), parameter :: n_up(3) = [0.0_wp, 0.0_wp, 1.0_wp]

  call check_delassus()
  call check_sphere()
  call check_rod_frictionless()
  call check_random_impacts()
  call check_refusals()
  call finish_tests('test_impact')

contains

  !> K L against Newton-Euler: dv = L/m, dw = I^-1 (r x L), dv_P = dv + dw x r.
  subroutine check_delassus()
    real(wp) :: inertia(3, 3), r(3), l(3), k(3, 3), dw(3), dv_p(3), rot(3, 3)
    integer :: trial
    do trial = 1, 5
      rot = matmul(rot_z(0.3_wp*trial), matmul(rot_y(-0.7_wp*trial), rot_x(1.1_wp*trial)))
      inertia = matmul(rot, matmul(diag([0.2_wp + 0.1_wp*trial, 0.5_wp, 0.9_wp]), transpose(rot)))
      r = [0.3_wp*trial, -0.2_wp, 0.5_wp - 0.1_wp*trial]
      l = [1.0_wp, -2.0_wp + trial, 0.7_wp]
      k = rigid_body_delassus(3.0_wp, inertia, r)
      dw = solve3(inertia, cross(r, l))
      dv_p = l/3.0_wp + cross(dw, r)
      call check(maxval(abs(matmul(k, l) - dv_p)) <= 1e-14_wp*maxval(abs(dv_p)), 'K L = Newton-Euler change')
      call check(maxval(abs(k - transpose(k))) <= 1e-15_wp*maxval(abs(k)), 'K symmetric')
    end do
  end subroutine check_delassus

  !> A solid sphere (m = 2 kg, R = 0.1 m, I = 2/5 m R^2) hits the plane z = 0
  !> with its contact point r = -R n: K = E/m + (5/(2m)) (E - n n^T).
  subroutine check_sphere()
    real(wp), parameter :: m = 2, radius = 0.1_wp
    real(wp) :: inertia(3, 3), k(3, 3), v(3), e, mu, vt, vn, ln, p_stop
    type(impact_outcome_t) :: out
    type(status_t) :: status
    integer :: i
    inertia = diag([1.0_wp, 1.0_wp, 1.0_wp])*0.4_wp*m*radius**2
    k = rigid_body_delassus(m, inertia, [0.0_wp, 0.0_wp, -radius])
    vt = 1.5_wp
    vn = -2.0_wp
    v = [vt*0.6_wp, vt*0.8_wp, vn]
    do i = 0, 2
      e = 0.5_wp*i
      ! Frictionless: Newton's v_n+ = -e v_n-; energy lost (1 - e^2) m vn^2/2.
      call resolve_impact(impact_law_t(restitution=e, mu=0), k, n_up, v, out, status)
      call check(status%ok(), 'sphere frictionless resolves')
      call check_close(out%normal_speed_after, -e*vn, 1e-14_wp, 0.0_wp, 'sphere frictionless v_n+ = -e v_n-')
      call check_close(norm2(out%velocity_after(1:2) - v(1:2)), 0.0_wp, 0.0_wp, 1e-15_wp, 'sphere frictionless v_t kept')
      call check_close(out%energy_lost, (1 - e**2)*m*vn**2/2, 1e-13_wp, 0.0_wp, 'sphere frictionless energy lost')
      ! Sticking from the start (mu large): v_t+ = 0; the impulse -2/7 m v_t,
      ! so the centre's tangential speed becomes 5/7 of v_t (no spin before).
      call resolve_impact(impact_law_t(restitution=e, mu=5.0_wp), k, n_up, v, out, status)
      call check(out%sticks_at_end .and. out%slip_stops == 1, 'sphere sticks')
      call check_close(norm2(out%velocity_after(1:2)), 0.0_wp, 0.0_wp, 1e-13_wp, 'sphere stick v_t+ = 0')
      call check_close(norm2(v(1:2) + out%impulse(1:2)/m), 5*vt/7, 1e-13_wp, 0.0_wp, 'sphere stick centre 5/7 v_t')
      call check_close(out%normal_speed_after, -e*vn, 1e-13_wp, 0.0_wp, 'sphere stick v_n+ = -e v_n-')
      ! Sliding throughout: mu (1+e) |vn| K_tt < vt with K_tt = 7/(2m).
      mu = 0.1_wp
      call resolve_impact(impact_law_t(restitution=e, mu=mu), k, n_up, v, out, status)
      ln = m*(1 + e)*abs(vn)
      call check(.not. out%sticks_at_end .and. out%slip_stops == 0, 'sphere slides throughout')
      call check_close(out%normal_impulse, ln, 1e-13_wp, 0.0_wp, 'sphere slide L_n = m (1+e) |v_n|')
      call check_close(norm2(out%impulse(1:2)), mu*ln, 1e-13_wp, 0.0_wp, 'sphere slide |L_t| = mu L_n')
      call check_close(norm2(out%velocity_after(1:2)), vt - mu*ln*3.5_wp/m, 1e-13_wp, 0.0_wp, &
        'sphere slide v_t+ = v_t - mu L_n K_tt')
      ! Slip stops part way: p_stop = vt/(mu K_tt) < L_n; then it sticks.
      mu = 0.25_wp
      p_stop = vt/(mu*3.5_wp/m)
      call resolve_impact(impact_law_t(restitution=e, mu=mu), k, n_up, v, out, status)
      if (p_stop < m*(1 + e)*abs(vn)) then
        call check(out%sticks_at_end .and. out%slip_stops == 1, 'sphere slip stops and sticks')
        call check_close(norm2(out%impulse(1:2)), 2*m*vt/7, 1e-13_wp, 0.0_wp, 'sphere slip-stop |L_t| = 2/7 m v_t')
        call check_close(out%normal_speed_after, -e*vn, 1e-13_wp, 0.0_wp, 'sphere slip-stop v_n+ = -e v_n-')
      end if
    end do
  end subroutine check_sphere

  !> A thin rod (m = 1 kg, length 1 m) tilted 30 deg, its lower end on the
  !> floor, frictionless: L_n = (1+e) |v_n|/(n . K n).
  subroutine check_rod_frictionless()
    real(wp) :: inertia(3, 3), k(3, 3), r(3), v(3), knn, e
    type(impact_outcome_t) :: out
    type(status_t) :: status
    e = 0.7_wp
    inertia = diag([1.0_wp/12, 1.0_wp/12, 1e-6_wp])
    inertia = matmul(rot_y(0.5235987755982988_wp), matmul(inertia, transpose(rot_y(0.5235987755982988_wp))))
    r = -0.5_wp*matmul(rot_y(0.5235987755982988_wp), [0.0_wp, 0.0_wp, 1.0_wp])
    k = rigid_body_delassus(1.0_wp, inertia, r)
    knn = 1 + dot_product(cross(r, n_up), solve3(inertia, cross(r, n_up)))
    v = [0.4_wp, 0.0_wp, -1.0_wp]
    call resolve_impact(impact_law_t(restitution=e, mu=0), k, n_up, v, out, status)
    call check(status%ok(), 'rod frictionless resolves')
    call check_close(out%normal_impulse, (1 + e)/knn, 1e-13_wp, 0.0_wp, 'rod L_n = (1+e)|v_n|/K_nn')
    call check_close(out%normal_speed_after, e, 1e-13_wp, 0.0_wp, 'rod v_n+ = -e v_n-')
    call check_close(norm2(out%impulse - out%normal_impulse*n_up), 0.0_wp, 0.0_wp, 1e-13_wp, 'rod no tangential impulse')
  end subroutine check_rod_frictionless

  !> Random bodies (inertia, arm) and velocities, e in [0, 1], mu in [0, 1.5].
  subroutine check_random_impacts()
    real(wp) :: inertia(3, 3), k(3, 3), r(3), v(3), rot(3, 3), e, mu, lt(3), gain, brute(3)
    type(impact_outcome_t) :: out
    type(status_t) :: status
    integer :: trial, compared, stuck, resumed
    stuck = 0
    resumed = 0
    compared = 0
    do trial = 1, 60
      rot = matmul(rot_z(1.3_wp*trial), matmul(rot_y(0.37_wp*trial), rot_x(-0.91_wp*trial)))
      inertia = matmul(rot, matmul(diag([0.05_wp + 0.3_wp*frac(0.61_wp*trial), 0.2_wp, 0.4_wp]), transpose(rot)))
      r = [sin(2.1_wp*trial), cos(1.7_wp*trial), -1.0_wp - 0.5_wp*frac(0.29_wp*trial)]*0.4_wp
      v = [2*sin(0.9_wp*trial), 2*cos(1.3_wp*trial), -0.3_wp - 2*frac(0.77_wp*trial)]
      e = frac(0.43_wp*trial)
      mu = 1.5_wp*frac(0.57_wp*trial)
      k = rigid_body_delassus(1.5_wp, inertia, r)
      if (trial > 30) then
        ! mu below what sticking needs (|K_tt^-1 K_tn|): slip must start again
        ! after it stops, or start from rest (trials 31-45 approach along n).
        mu = 0.5_wp*norm2(solve2(k(1:2, 1:2), k(1:2, 3)))
        if (trial <= 45) then
          v(1:2) = 0
        else
          v(1:2) = 0.2_wp*v(1:2)
        end if
      end if
      status = status_t()
      call resolve_impact(impact_law_t(restitution=e, mu=mu), k, n_up, v, out, status)
      if (.not. status%ok()) then
        ! Only a jam may refuse; it must say so.
        call check(.false., 'random impact refused: '//status%text())
        cycle
      end if
      lt = out%impulse - out%normal_impulse*n_up
      if (out%slip_stops > 0 .and. out%sticks_at_end) stuck = stuck + 1
      if (.not. out%sticks_at_end .and. (out%slip_stops > 0 .or. norm2(v(1:2)) == 0)) resumed = resumed + 1
      call check(out%normal_impulse > 0, 'random impact: pushes the bodies apart')
      call check(norm2(lt) <= mu*out%normal_impulse*(1 + 1e-9_wp) + 1e-14_wp, 'random impact: inside the cone')
      call check(maxval(abs(matmul(k, out%impulse) - (out%velocity_after - v))) <= 1e-12_wp*norm2(v), &
        'random impact: K L = v+ - v-')
      call check_close(dot_product(out%impulse, n_up), out%normal_impulse, 1e-12_wp, 0.0_wp, &
        'random impact: n . L = p')
      gain = -out%energy_lost
      call check(gain <= 1e-12_wp*dot_product(v, v), 'random impact: no energy created')
      call check(out%normal_speed_after >= -1e-12_wp*norm2(v), 'random impact: separates or slides on')
      ! The brute-force reference (eps = 1e-4 |v|: agreement to a few eps) for
      ! 25 of them (it costs a second each).
      if (trial > 15 .and. .not. (trial > 30 .and. mod(trial, 3) == 0)) cycle
      brute = brute_force_after(k, n_up, v, e, mu)
      compared = compared + 1
      call check(norm2(brute - out%velocity_after) <= 3e-4_wp*norm2(v), 'random impact: brute force agrees')
    end do
    call check(compared == 25, 'random impacts: 25 compared with the brute force')
    ! The set covers both ends of a stopped slip: sticking, and slip again.
    call check(stuck > 5 .and. resumed > 5, 'random impacts: slip stops, then sticks or slips again')
    print '(a, i0, a, i0)', 'random impacts: stuck after a stop ', stuck, ', slipped again ', resumed
  end subroutine check_random_impacts

  !> The same impact by many small Runge-Kutta steps in p with Coulomb's law
  !> regularized, f_t = -mu v_t/sqrt(|v_t|^2 + eps^2), no phases: compression
  !> until v_n >= 0, restitution until the work is back to (1 - e^2) W_c (each
  !> end to within one step; the steps are 1e-5 of the impulse's scale).
  function brute_force_after(k, n, v0, e, mu) result(v)
    real(wp), intent(in) :: k(3, 3), n(3), v0(3), e, mu
    real(wp) :: v(3)
    real(wp) :: h, eps, work, wc, target, k1(3), k2(3), k3(3), k4(3), w(4)
    logical :: compressing
    integer :: step
    eps = 1e-4_wp*norm2(v0)
    h = abs(dot_product(n, v0))/dot_product(n, matmul(k, n))*1e-6_wp
    v = v0
    work = 0
    compressing = .true.
    target = -huge(1.0_wp)
    do step = 1, 50000000
      call regularized_rate(k, n, mu, eps, v, k1, w(1))
      call regularized_rate(k, n, mu, eps, v + h/2*k1, k2, w(2))
      call regularized_rate(k, n, mu, eps, v + h/2*k2, k3, w(3))
      call regularized_rate(k, n, mu, eps, v + h*k3, k4, w(4))
      v = v + h/6*(k1 + 2*k2 + 2*k3 + k4)
      work = work + h/6*(w(1) + 2*w(2) + 2*w(3) + w(4))
      if (compressing .and. dot_product(n, v) >= 0) then
        compressing = .false.
        wc = work
        target = (1 - e**2)*wc
      end if
      if (.not. compressing .and. work >= target) exit
    end do
  end function brute_force_after

  !> The regularized slip equations of brute_force_after.
  subroutine regularized_rate(k, n, mu, eps, x, dx, dw)
    real(wp), intent(in) :: k(3, 3), n(3), mu, eps, x(3)
    real(wp), intent(out) :: dx(3), dw
    real(wp) :: xt(3)
    xt = x - dot_product(n, x)*n
    dx = matmul(k, n - mu*xt/sqrt(dot_product(xt, xt) + eps**2))
    dw = dot_product(n, x)
  end subroutine regularized_rate

  !> K must be symmetric positive definite; the law's e in [0, 1], mu >= 0.
  subroutine check_refusals()
    real(wp) :: k(3, 3)
    type(impact_outcome_t) :: out
    type(status_t) :: status
    k = diag([1.0_wp, 2.0_wp, -0.5_wp])
    call resolve_impact(impact_law_t(restitution=0.5_wp, mu=0.3_wp), k, n_up, [0.0_wp, 0.0_wp, -1.0_wp], out, status)
    call check(.not. status%ok() .and. index(status%text(), 'positive definite') > 0, 'indefinite K refused')
    k = diag([1.0_wp, 2.0_wp, 3.0_wp])
    k(1, 2) = 0.1_wp
    status = status_t()
    call resolve_impact(impact_law_t(restitution=0.5_wp, mu=0.3_wp), k, n_up, [0.0_wp, 0.0_wp, -1.0_wp], out, status)
    call check(.not. status%ok() .and. index(status%text(), 'symmetric') > 0, 'unsymmetric K refused')
    k(1, 2) = 0
    status = status_t()
    call resolve_impact(impact_law_t(restitution=1.5_wp, mu=0.3_wp), k, n_up, [0.0_wp, 0.0_wp, -1.0_wp], out, status)
    call check(.not. status%ok() .and. index(status%text(), 'restitution 1.5') > 0, 'e > 1 refused')
    status = status_t()
    call resolve_impact(impact_law_t(restitution=0.5_wp, mu=-0.1_wp), k, n_up, [0.0_wp, 0.0_wp, -1.0_wp], out, status)
    call check(.not. status%ok() .and. index(status%text(), 'mu -0.1') > 0, 'mu < 0 refused')
    status = status_t()
    call resolve_impact(impact_law_t(restitution=0.5_wp, mu=0.3_wp), k, n_up, [1.0_wp, 0.0_wp, 0.5_wp], out, status)
    call check(status%ok() .and. .not. out%approaching .and. norm2(out%impulse) == 0, 'separating: no impulse')
  end subroutine check_refusals

  pure function diag(d) result(m)
    real(wp), intent(in) :: d(3)
    real(wp) :: m(3, 3)
    m = 0
    m(1, 1) = d(1); m(2, 2) = d(2); m(3, 3) = d(3)
  end function diag

  pure real(wp) function frac(x)
    real(wp), intent(in) :: x
    frac = x - floor(x)
  end function frac

  pure function solve2(a, b) result(x)
    real(wp), intent(in) :: a(2, 2), b(2)
    real(wp) :: x(2), det
    det = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
    x = [a(2, 2)*b(1) - a(1, 2)*b(2), a(1, 1)*b(2) - a(2, 1)*b(1)]/det
  end function solve2

  !> A x = b by Cramer's rule (3 x 3).
  pure function solve3(a, b) result(x)
    real(wp), intent(in) :: a(3, 3), b(3)
    real(wp) :: x(3), det
    det = dot_product(a(:, 1), cross(a(:, 2), a(:, 3)))
    x(1) = dot_product(b, cross(a(:, 2), a(:, 3)))/det
    x(2) = dot_product(a(:, 1), cross(b, a(:, 3)))/det
    x(3) = dot_product(a(:, 1), cross(a(:, 2), b))/det
  end function solve3
end program test_impact

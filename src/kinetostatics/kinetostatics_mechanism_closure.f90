!> The mechanism's loop closure (kinetostatics_mechanism): positions.
!>
!> Loops (3.24)-(3.33). Each loop names its closure measurements g (with target
!> values) and as many dependent coordinates beta. f(beta, q) = g - target = 0 is
!> solved from the previous solution (warm start): first by Newton steps with
!> the analytic Jacobian J_beta (one velocity pass per column, (3.21)), which
!> converge in one or two steps from a warm start; if that does not reach the
!> tolerance, by MINPACK's HYBRJ with the same Jacobian (the thesis's solver).
!> A Newton iterate outside a surface's parameter domain during a run (warm
!> start) ends the solve with STATUS_DOMAIN at once, the scalars left at that
!> iterate: from a warm start the first Newton step is right to second order,
!> so the solution lies outside too; the integrator shortens its step, and the
!> root functions of the domain edges see where the joint went.
!> Then beta' = -J_beta^-1 f^ (3.30), beta'' = -J_beta^-1 f^' (3.31), and the cut
!> forces lambda = -J_beta^-T Q^_beta ((3.33): the printed form lacks the inverse).
!> J_beta (and J_x below) are block diagonal, one block per set of loops and
!> rate constraints that share an entry, each column filled by a velocity
!> pass over only the elements its rate reaches, factored and solved block by
!> block (kinetostatics_closure_blocks; one block and full passes with
!> set_blocked(.false.) or an element of unknown links).
submodule (kinetostatics_mechanism) kinetostatics_mechanism_closure
  implicit none (type, external)

contains

  module procedure closure_system_residual
    call residual_at(self%mechanism, self%work, x, .true., f, status)
  end procedure closure_system_residual

  !> The closure residual at beta = x: a position pass over every element
  !> (full), or, after only beta changed since the last position pass (the
  !> Newton iterates of set_positions), the position maps of the elements
  !> beta reaches: the others' inputs and so their outputs are unchanged
  !> (for the rider: the pelvis's surface joint is not evaluated again).
  !> Same values to the bit either way. `last` (a pass over what beta
  !> reaches, expected to be the solve's last: after the polishing step)
  !> takes the elements' position_complete: a lazy surface joint computes
  !> its whole geometry there, which J_beta at the solution needs next,
  !> instead of its frame first and the whole again (the same numbers).
  subroutine residual_at(self, work, x, full, f, status, last)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: x(:)
    logical, intent(in) :: full
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: last
    integer :: k
    logical :: complete
    complete = .false.
    if (present(last)) complete = last
    do k = 1, self%r
      work%scalars(self%beta(k))%q = x(k)
    end do
    f = 0
    if (full) then
      call self%position_pass(work, status)
    else if (complete) then
      work%evaluation = work%evaluation + 1
      do k = 1, size(self%beta_pass)
        call work%elements(self%beta_pass(k))%e%position_complete(work%frames, work%scalars, status)
        if (.not. status%ok()) exit
      end do
    else
      work%evaluation = work%evaluation + 1
      do k = 1, size(self%beta_pass)
        call work%elements(self%beta_pass(k))%e%position(work%frames, work%scalars, status)
        if (.not. status%ok()) exit
      end do
    end if
    if (.not. status%ok()) return
    do k = 1, self%r
      f(k) = work%scalars(self%closure(k))%q - self%target(k)
    end do
  end subroutine residual_at

  module procedure closure_system_jacobian
    integer :: k
    associate (m => self%mechanism, work => self%work)
      do k = 1, m%r
        work%scalars(m%beta(k))%q = x(k)
      end do
      jac = 0
      call m%position_pass(work, status)
      if (.not. status%ok()) return
      call closure_jacobian(m, work, jac)
    end associate
  end procedure closure_system_jacobian

  !> J_beta column by column: velocity passes with q' = 0, beta' = e_k (3.21),
  !> each over the elements that rate reaches (kinetostatics_closure_blocks).
  !> Destroys the velocity state.
  subroutine closure_jacobian(self, work, jac)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(out) :: jac(:, :)
    call fill_closure(self, work, self%r)
    call work%blocks%assemble(.false., jac)
  end subroutine closure_jacobian

  !> Columns 1..last of J_x (last = r: J_beta) into the blocks.
  subroutine fill_closure(self, work, last)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: last
    call work%blocks%fill(work%elements, self%reach, work%frames, work%scalars, self%unknowns, self%rows, last)
  end subroutine fill_closure

  !> With rate constraints: J_x of the unknown rates [beta'; sigma'] against
  !> [g'; c] (filled), LU-factored block by block.
  subroutine factor_filled_rates(self, work, status)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    type(status_t), intent(inout) :: status
    type(status_t) :: lapack
    integer :: zero_pivot
    if (self%nd == 0 .or. .not. status%ok()) return
    call work%blocks%factor(.true., lapack, zero_pivot)
    if (.not. lapack%ok()) then
      if (zero_pivot > self%r) then
        call set_status(status, STATUS_NOT_CONVERGED, 'the rate constraints are singular: the rate of '''// &
          trim(self%scalar_names(self%sigma(zero_pivot - self%r)))//''' does not move their outputs')
      else
        call set_status(status, STATUS_NOT_CONVERGED, 'the closure and rate constraints are singular at '// &
                        describe_dependent(self, zero_pivot))
      end if
    end if
  end subroutine factor_filled_rates

  !> J_beta at the current positions, LU-factored block by block.
  subroutine factor_closure(self, work, status)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    type(status_t), intent(inout) :: status
    call fill_closure(self, work, self%r)
    call factor_jbeta(self, work, status)
  end subroutine factor_closure

  !> With rate constraints: J_x filled and factored. Destroys the velocity state.
  subroutine factor_rates(self, work, status)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    type(status_t), intent(inout) :: status
    if (self%nd == 0 .or. .not. status%ok()) return
    call fill_closure(self, work, self%r + self%nd)
    call factor_filled_rates(self, work, status)
  end subroutine factor_rates

  !> LU of the filled J_beta blocks.
  subroutine factor_jbeta(self, work, status)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    type(status_t), intent(inout) :: status
    type(status_t) :: lapack
    integer :: zero_pivot
    call work%blocks%factor(.false., lapack, zero_pivot)
    if (.not. lapack%ok()) then
      call set_status(status, STATUS_NOT_CONVERGED, 'the closure Jacobian is singular: '// &
                      describe_dependent(self, zero_pivot)//' does not move the closure measurements')
    end if
  end subroutine factor_jbeta

  function describe_dependent(self, k) result(text)
    class(mechanism_t), intent(in) :: self
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: l, m, count
    count = 0
    text = 'dependent coordinate '''//trim(self%scalar_names(self%beta(k)))//''''
    do l = 1, size(self%loops)
      do m = 1, size(self%loops(l)%dependents)
        count = count + 1
        if (count == k) text = text//' of loop '''//self%loops(l)%name//''''
      end do
    end do
  end function describe_dependent

  !> The loop whose closure is worst at the current positions.
  function worst_loop(self, work) result(text)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(in) :: work
    character(len=:), allocatable :: text
    integer :: l, m
    real(wp) :: worst, e
    character(len=16) :: num
    worst = -1
    text = ''
    do l = 1, size(self%loops)
      do m = 1, size(self%loops(l)%measurements)
        e = abs(work%scalars(self%loops(l)%measurements(m))%q - self%loops(l)%targets(m))
        if (e > worst) then
          worst = e
          write (num, '(es10.3)') e
          text = 'loop '''//self%loops(l)%name//''' (measurement '''// &
                 trim(self%scalar_names(self%loops(l)%measurements(m)))//''' off by '//trim(adjustl(num))//')'
        end if
      end do
    end do
  end function worst_loop

  !> Sets q, closes the loops (beta from the last solution), leaves the
  !> positions evaluated and J_beta (and J_x with rate constraints) factored.
  !> Sizes the workspace on its first use; set_velocities, set_accelerations
  !> and inverse_dynamics then take the same workspace.
  module procedure set_positions
    type(nonlinear_result_t) :: result
    type(closure_system_t) :: system
    type(status_t) :: solve_status
    integer :: k, it, fresh
    real(wp) :: size_res, last
    logical :: converged, predicted, chord, polished, retry

    if (any(work%dims /= self%workspace_dims)) call self%prepare_workspace(work)

    predicted = self%r > 0 .and. work%converged
    if (predicted) call predict_dependents(self, work, q)
    do k = 1, self%f
      work%scalars(self%q(k))%q = q(k)
    end do
    if (self%r == 0) then
      call self%position_pass(work, status)
      call factor_rates(self, work, status)
      return
    end if
    work%closure_solves = work%closure_solves + 1
    associate (x => work%x_r, start => work%start_r, res => work%res_r)
    ! the warm start: the last solution, kept in start_r after a failed solve
    ! (whose scalars hold its last iterate); before any solution, the scalars
    if (work%converged .or. .not. work%warm) then
      do k = 1, self%r
        start(k) = work%scalars(self%beta(k))%q
      end do
    end if
    work%converged = .false.
    retry = work%solve_failed
    work%solve_failed = .true.   ! until a solution is found below
    ! Newton from the warm start, moved by the predictor; after the predictor
    ! first with J_beta of the last solution (still factored: each step costs
    ! one position pass instead of r velocity passes), then, if that contracts
    ! slowly, with J_beta at the iterate (at most 4 such steps)
    x = start
    if (predicted) x = start - work%work_r
    if (retry .and. work%warm .and. .not. predicted) call nearer_solution(self, work, q, x)
    converged = .false.
    chord = predicted
    polished = .false.
    last = huge(1.0_wp)
    fresh = 0
    do it = 1, 10
      ! the first pass at the new q over every element, then only beta changes
      call residual_at(self, work, x, it == 1, res, status, last=polished)
      if (.not. status%ok()) then
        if (status%code == STATUS_DOMAIN .and. work%warm) return   ! see the module comment
        exit
      end if
      size_res = maxval(abs(res))
      if (size_res <= 1e-3_wp*self%closure_tolerance) then
        ! a chord step converges only linearly: one more, so that beta is as
        ! exact as after a Newton step (a noisier right-hand side costs the
        ! integrator more steps than the position pass), unless the residual
        ! is already at the rounding floor (rider: ~2-4e-15 m after a polish,
        ! 99 % below 7e-15), which a further step cannot go below
        converged = .not. chord .or. polished .or. size_res <= 1e-4_wp*self%closure_tolerance
        if (converged) exit
        polished = .true.
        call work%blocks%solve(.false., res, .false.)
        x = x - res
        cycle
      end if
      if (chord .and. size_res > 0.1_wp*last) chord = .false.   ! contraction too slow: a fresh J_beta
      if (.not. chord) then
        if (fresh == 4) exit
        fresh = fresh + 1
        call factor_closure(self, work, solve_status)
        if (.not. solve_status%ok()) exit
      end if
      last = size_res
      call work%blocks%solve(.false., res, .false.)
      x = x - res
    end do
    if (.not. converged) then
      if (status%ok()) then
        call residual_at(self, work, x, .false., res, status)
        converged = status%ok() .and. maxval(abs(res)) <= self%closure_tolerance
      end if
    end if
    if (.not. converged) then
      ! HYBRJ from the warm start (thesis (3.25) with MINPACK's safeguards)
      status = status_t()
      x = start
      work%hybrj_solves = work%hybrj_solves + 1
      system%mechanism => self
      system%work => work
      call solve_nonlinear(system, x, self%closure_options, result, solve_status)
      call residual_at(self, work, x, .true., res, status)
      if (.not. solve_status%ok() .or. .not. status%ok()) then
        if (status%ok()) status = solve_status
        call prefix_status(status, 'closure failed at '//worst_loop(self, work))
        return
      end if
      ! polish with Newton steps
      do it = 1, 3
        if (maxval(abs(res)) <= 1e-3_wp*self%closure_tolerance) exit
        call factor_closure(self, work, status)
        if (.not. status%ok()) return
        call work%blocks%solve(.false., res, .false.)
        x = x - res
        call residual_at(self, work, x, .true., res, status)
        if (.not. status%ok()) return
      end do
      if (maxval(abs(res)) > self%closure_tolerance) then
        call set_status(status, STATUS_NOT_CONVERGED, 'closure failed at '//worst_loop(self, work))
        return
      end if
    end if
    end associate
    ! J_beta at the solution; with rate constraints it is the first r columns
    ! of J_x, which are filled anyway
    if (self%nd > 0) then
      call fill_closure(self, work, self%r + self%nd)
      call factor_jbeta(self, work, status)
    else
      call factor_closure(self, work, status)
    end if
    if (.not. status%ok()) then
      call prefix_status(status, 'closure')
      return
    end if
    call check_branches(self, work, status)
    if (.not. status%ok()) return
    work%warm = .true.
    work%converged = .true.
    work%solve_failed = .false.
    call keep_solution(self, work, q)
    call factor_filled_rates(self, work, status)
  end procedure set_positions

  !> The tangent predictor of the warm start: the elements still hold the
  !> geometry of the last solution (q0, beta0) and J_beta is factored there,
  !> so one velocity pass with q' = q - q0, beta' = 0 gives J_q (q - q0), and
  !> beta0 - J_beta^-1 J_q (q - q0) is the start, right to second order in
  !> q - q0 (a rolling ball turns by radians between two right-hand sides of
  !> a large step: from the old beta Newton can reach the other branch).
  !> Leaves the correction J_beta^-1 J_q (q - q0) in work_r; destroys the
  !> velocity state.
  subroutine predict_dependents(self, work, q)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: q(:)
    integer :: k
    work%scalars%qd = 0
    do k = 1, self%f
      work%scalars(self%q(k))%qd = q(k) - work%scalars(self%q(k))%q
    end do
    call self%velocity_pass(work)
    do k = 1, self%r
      work%work_r(k) = work%scalars(self%closure(k))%qd
    end do
    call work%blocks%solve(.false., work%work_r, .false.)
    if (self%nd > 0 .or. size(self%kinematic) > 0) return
    ! The second-order term: along beta(s) = beta(q0 + s (q - q0)), beta'(0) =
    ! -work_r, and g'' = 0 gives beta''(0) = -J_beta^-1 g''|beta''=0 (an
    ! acceleration pass with the velocities of beta'(0) and no accelerations).
    ! It is taken only while it is below a tenth of the first-order term
    ! (a Taylor series that converges fast; on a jump of metres it would
    ! spoil the start); it saves a Newton step on most steps of an integrator.
    do k = 1, self%r
      work%scalars(self%beta(k))%qd = -work%work_r(k)
    end do
    do k = 1, size(self%beta_pass)   ! only beta' changed
      call work%elements(self%beta_pass(k))%e%velocity(work%frames, work%scalars)
    end do
    work%scalars%qdd = 0
    call self%acceleration_pass(work)
    do k = 1, self%r
      work%res_r(k) = work%scalars(self%closure(k))%qdd
    end do
    call work%blocks%solve(.false., work%res_r, .false.)
    if (0.5_wp*maxval(abs(work%res_r)) <= 0.1_wp*maxval(abs(work%work_r))) &
      work%work_r = work%work_r + 0.5_wp*work%res_r
  end subroutine predict_dependents

  !> The solution just found (beta in the scalars, at `q`) joins the recent
  !> ones, in place of the oldest.
  subroutine keep_solution(self, work, q)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: q(:)
    integer :: k
    associate (slot => work%recent_next)
      do k = 1, self%r
        work%recent_r(k, slot) = work%scalars(self%beta(k))%q
      end do
      work%recent_q(:, slot) = q
      work%recent_charts(slot) = charts_changed(self, work)
      slot = 1 + mod(slot, recent_solutions)
    end associate
  end subroutine keep_solution

  !> After a failed solve: the warm start `x` is the recent solution found
  !> at the q nearest `q` (max norm), in the same charts. The last solution
  !> alone will not do: the integrator's rejected trial step leaves its
  !> solutions as the last ones, and from there, at the retry's q far
  !> behind, Newton can leave the surface's domain on every retry (a double
  !> ring on the bowl slide, docs/vehicles.md: 4.7 m behind).
  subroutine nearer_solution(self, work, q, x)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(in) :: work
    real(wp), intent(in) :: q(:)
    real(wp), intent(inout) :: x(:)
    integer :: charts, k, best
    real(wp) :: distance, nearest
    charts = charts_changed(self, work)
    best = 0
    nearest = huge(1.0_wp)
    do k = 1, recent_solutions
      if (work%recent_charts(k) /= charts) cycle
      distance = maxval(abs(q - work%recent_q(:, k)))
      if (distance < nearest) then
        nearest = distance
        best = k
      end if
    end do
    if (best > 0) x = work%recent_r(:, best)
  end subroutine nearer_solution

  !> How many times the elements' charts have changed (a solution's
  !> coordinates hold only in the charts it was found in).
  integer function charts_changed(self, work) result(n)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(in) :: work
    integer :: k
    n = 0
    do k = 1, self%n_elements
      n = n + work%elements(k)%e%chart_changes()
    end do
  end function charts_changed

  !> Every loop with a branch condition on it (set_loop_branch).
  subroutine check_branches(self, work, status)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    type(status_t), intent(inout) :: status
    integer :: k
    real(wp) :: c
    do k = 1, size(self%loops)
      associate (pair => self%loops(k)%antiparallel)
        if (pair(1) == 0) cycle
        c = dot_product(work%frames(pair(1))%rot(:, 3), work%frames(pair(2))%rot(:, 3))
        if (c > 0) then
          call set_status(status, STATUS_DOMAIN, 'loop '''//self%loops(k)%name//''' closed on the branch '// &
            'with parallel normals (z of '''//trim(self%frame_names(pair(1)))//''' . z of '''// &
            trim(self%frame_names(pair(2)))//''' = '//format_short(c)//'), not on the physical one')
          work%converged = .false.
          return
        end if
      end associate
    end do
  end subroutine check_branches

  !> At the start: the loops must close from the given beta and J_beta must be
  !> well conditioned (reciprocal condition number above 1e-10).
  module procedure check_start
    real(wp) :: rcond
    real(wp), allocatable :: jbeta(:, :), jlu(:, :)
    integer, allocatable :: pivots(:)
    integer :: i, k
    character(len=16) :: num
    if (.not. status%ok()) return
    work%warm = .false.
    work%converged = .false.
    call self%set_positions(work, q, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'at the start')
      return
    end if
    if (self%r == 0) return
    ! the whole J_beta (its blocks already factored without a zero pivot)
    allocate (jbeta(self%r, self%r), pivots(self%r))
    call work%blocks%assemble(.false., jbeta)
    jlu = jbeta
    call lu_factor(jlu, pivots, status)
    if (status%ok()) call lu_reciprocal_condition(jlu, one_norm(jbeta), rcond, status)
    if (status%ok() .and. rcond < 1e-10_wp) then
      k = minloc([(abs(jlu(i, i)), i = 1, self%r)], dim=1)   ! the weakest pivot
      write (num, '(es10.3)') rcond
      call set_status(status, STATUS_INVALID_INPUT, 'at the start the closure Jacobian is singular '// &
        '(reciprocal condition '//trim(adjustl(num))//'): '//describe_dependent(self, k)// &
        ' is not determined by its closure measurements')
    end if
  end procedure check_start

  !> max |g - target| over all closure measurements at the current positions.
  module procedure closure_residual
    integer :: k
    e = 0
    do k = 1, self%r
      e = max(e, abs(work%scalars(self%closure(k))%q - self%target(k)))
    end do
  end procedure closure_residual
end submodule kinetostatics_mechanism_closure

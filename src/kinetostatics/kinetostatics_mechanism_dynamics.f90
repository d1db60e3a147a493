!> The mechanism's equations of motion (kinetostatics_mechanism).
!>
!> Equations of motion (3.34)-(3.36): the inverse dynamics Q_bar(q, s, s')
!> (generalized forces of d'Alembert + applied forces at the speeds, loops and
!> velocity constraints closed by lambda, mu) is affine in s': Q_bar = Q_bar0 -
!> M s'. One pass with s' = 0 (inertia, gravity and the explicit laws) gives
!> Q_bar0 = -Q^ and the normal forces N0.
!>
!> Normal forces and scaled laws: every contact's normal force N (rules in
!> kinetostatics_contact) is linear in the loads of a force pass, so
!> N = N0 + G q'' + sum_k H_k |N_c(k)|, where the last sum runs over the scaled
!> laws k (load |N_c(k)| u_k with u_k from the law, e.g. Coulomb friction
!> u = -mu w/|w| (4.28)). With s_j = sign N_j, P_k and H_k the generalized
!> forces and normal forces of the unit load u_k alone (as one force pass with
!> it would give them), and the contacts j of the scaled laws as
!> extra unknowns, the equations of motion are the exact block system
!>     [ M            -sum_k P_k s_j(k) e_j(k)^T   ] [q'']   [Q_bar0]
!>     [ -G_j   I - sum_k H_j,k s_j(k) e_j(k)^T    ] [N_j] = [N0_j  ],
!> its signs iterated until consistent (normally at once; no consistent signs:
!> a Painleve-type paradox, reported). The other contacts' N follow from the
!> affine form. The law's power is |N| times its unit power.
submodule (kinetostatics_mechanism) kinetostatics_mechanism_dynamics
  implicit none (type, external)

contains

  !> s' from M(q) s' + Q^(q, s) = Q_applied (3.36) (s = q' without rate
  !> constraints and kinematic coordinates; qd is s, qdd is s'), with every force law
  !> and the normal forces of the contacts (see the module comment). Leaves,
  !> in the workspace, M in `mass` (not for a chain or tree of bodies, which
  !> takes the recursion: kinetostatics_mechanism_tree), Q_bar0 in `bias`, q''
  !> in `qdd`, the normal forces in `normal`, the laws' powers in `law_power`.
  !> The velocity and acceleration states are
  !> overwritten (use `evaluate` for a consistent state). Called again at the
  !> same (t, q, s) with the same laws switched on and no position pass or law
  !> evaluation in between with this workspace, it returns the
  !> results it left (the positions and laws are still those of that state)
  !> and sets the velocities again.
  module procedure dynamics
    real(wp) :: s_old
    type(status_t) :: lapack
    integer :: i, j, k, c, nc, ns, nb, it, column
    logical :: consistent

    if (any(work%dims /= self%workspace_dims)) call self%prepare_workspace(work)
    if (work%known_evaluation == work%evaluation .and. t == work%known_t) then
      if (all(q == work%known_q) .and. all(qd == work%known_s) .and. &
          same_switches(self, work)) then
        qdd = work%qdd
        call self%set_velocities(work, qd)
        work%dynamics_reused = work%dynamics_reused + 1
        return
      end if
    end if
    if (self%tree%active) then   ! a chain or tree of bodies: linear time (kinetostatics_mechanism_tree)
      call tree_dynamics(self, work, t, q, qd, qdd, status)
      if (.not. status%ok()) return
      work%law_power(:) = work%unit_power
      call remember_dynamics(self, work, t, q, qd)
      return
    end if
    qdd = 0
    nc = size(self%contacts)
    ns = size(self%scaled_laws)
    nb = size(self%block_contact)
    call self%set_positions(work, q, status)
    if (.not. status%ok()) return
    call self%set_velocities(work, qd)
    call bias_forces(self, work, t, status)
    if (.not. status%ok()) return
    if (nc > 0) call self%normal_forces(work, work%lambda, work%n0)

    ! M and G, all velocities zero, applied forces off
    call rest_velocities(work%frames, work%scalars)
    if (self%twist_route) then
      call twist_mass_matrix(self, work)
    else
      do i = 1, self%ns
        call full_mass_column(self, work, i)
      end do
    end if
    if (.not. self%twist_route) then   ! (the twist route's M is symmetric and left its lower triangle in chol)
      do i = 1, self%ns   ! symmetric part's lower triangle, the factor's input (no temporary)
        do k = i, self%ns
          work%chol(k, i) = 0.5_wp*(work%mass(k, i) + work%mass(i, k))
        end do
      end do
    end if
    call cholesky_factor(work%chol, lapack, column)
    if (.not. lapack%ok()) then
      call no_inertia(self, column, status)
      return
    end if
    if (ns == 0) then
      work%qdd(:) = work%bias
      call cholesky_solve(work%chol, work%qdd, status)
      qdd = work%qdd
      call affine_normal_forces(self, work, qdd)
      work%law_power(:) = work%unit_power
      call remember_dynamics(self, work, t, q, qd)
      return
    end if

    ! scaled laws: their unit loads alone, then the block system
    if (self%twist_route) then
      call twist_unit_loads(self, work)
    else
      do k = 1, ns
        call self%inverse_dynamics(work, .false., .false., self%scaled_laws(k))
        work%p_mat(:, k) = work%gq
        call self%normal_forces(work, work%lambda, work%h_mat(:, k))
      end do
    end if
    work%signs = 1
    consistent = .false.
    do it = 1, 6
      work%block = 0
      work%block(1:self%ns, 1:self%ns) = work%mass
      do j = 1, nb
        work%block(self%ns + j, 1:self%ns) = -work%g_mat(self%block_contact(j), :)
        work%block(self%ns + j, self%ns + j) = 1
      end do
      do k = 1, ns
        j = self%block_row(k)
        work%block(1:self%ns, self%ns + j) = work%block(1:self%ns, self%ns + j) &
                                                  - work%p_mat(:, k)*work%signs(j)
        do i = 1, nb
          work%block(self%ns + i, self%ns + j) = work%block(self%ns + i, self%ns + j) &
                                               - work%h_mat(self%block_contact(i), k)*work%signs(j)
        end do
      end do
      work%block_rhs(1:self%ns) = work%bias
      do j = 1, nb
        work%block_rhs(self%ns + j) = work%n0(self%block_contact(j))
      end do
      call lu_factor(work%block, work%ipiv_block, lapack)
      if (.not. lapack%ok()) then
        call set_status(status, STATUS_DOMAIN, 'the equations of motion with friction proportional to '// &
                        'the normal forces are singular')
        return
      end if
      call lu_solve(work%block, work%ipiv_block, work%block_rhs, status)
      consistent = .true.
      do j = 1, nb
        s_old = work%signs(j)
        if (work%block_rhs(self%ns + j)*s_old < 0) then
          consistent = .false.
          work%signs(j) = -s_old
        end if
      end do
      if (consistent) exit
    end do
    if (.not. consistent) then
      call set_status(status, STATUS_DOMAIN, 'friction proportional to the normal forces: no consistent '// &
                      'signs of the normal forces (the friction law has no unique solution here, a '// &
                      'Painleve-type paradox)')
      return
    end if
    qdd = work%block_rhs(1:self%ns)
    work%qdd = qdd
    call affine_normal_forces(self, work, qdd)
    do k = 1, ns
      j = self%block_row(k)
      work%normal = work%normal + work%h_mat(:, k)*work%signs(j)*work%block_rhs(self%ns + j)
    end do
    do j = 1, nb
      work%normal(self%block_contact(j)) = work%block_rhs(self%ns + j)
    end do
    work%law_power = work%unit_power
    do k = 1, ns
      c = self%laws(self%scaled_laws(k))%law%contact
      work%law_factor(self%scaled_laws(k)) = abs(work%normal(c))
      work%law_power(self%scaled_laws(k)) = abs(work%normal(c))*work%unit_power(self%scaled_laws(k))
    end do
    call remember_dynamics(self, work, t, q, qd)
  end procedure dynamics

  !> Q_bar0 = -Q^ (the module comment) in the workspace's `bias`, at the
  !> positions and velocities set: the laws evaluated at t, every law at
  !> full load, the inverse dynamics at s' = 0 with inertia, the applied
  !> forces and the explicit laws. Leaves the acceleration state at s' = 0.
  module procedure bias_forces
    call self%evaluate_laws(work, t, status)
    if (.not. status%ok()) return
    work%law_factor = 1
    work%work_f = 0
    call self%set_accelerations(work, work%work_f)
    call self%inverse_dynamics(work, .true., .true., LOADS_EXPLICIT)
    work%bias(:) = work%gq   ! (:): no reallocation test
  end procedure bias_forces

  !> The status of a mass matrix that is not positive definite, at the
  !> speed `column` (its factor's first zero or negative pivot).
  module procedure no_inertia
    call set_status(status, STATUS_DOMAIN, 'the mass matrix is not positive definite: generalized '// &
      'coordinate '''//trim(self%scalar_names(self%q(self%speeds(column))))//''' has no inertia (a massless body or '// &
      'a mass without rotational inertia on a pure rotation)')
  end procedure no_inertia

  !> Column i of M and of G by inverse-dynamics passes (the route for a
  !> mechanism with an element of unknown links): s' = e_i, velocities zero,
  !> applied forces off.
  subroutine full_mass_column(self, work, i)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: i
    work%work_f = 0
    work%work_f(i) = 1
    call self%set_accelerations(work, work%work_f)
    call self%inverse_dynamics(work, .true., .false., LOADS_NONE)
    work%mass(:, i) = -work%gq
    if (size(self%contacts) > 0) call self%normal_forces(work, work%lambda, work%g_mat(:, i))
  end subroutine full_mass_column

  subroutine remember_dynamics(self, work, t, q, qd)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: t, q(:), qd(:)
    integer :: k
    work%known_t = t
    work%known_q(:) = q
    work%known_s(:) = qd
    do k = 1, self%n_laws
      work%known_active(k) = work%laws(k)%law%active
    end do
    work%known_evaluation = work%evaluation
  end subroutine remember_dynamics

  !> Every law switched on or off as at the last completed `dynamics`.
  logical function same_switches(self, work) result(same)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(in) :: work
    integer :: k
    same = .true.
    do k = 1, self%n_laws
      if (work%laws(k)%law%active .neqv. work%known_active(k)) same = .false.
    end do
  end function same_switches

  !> N = N0 + G q'' for every contact (without the scaled laws' share).
  subroutine affine_normal_forces(self, work, qdd)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: qdd(:)
    integer :: i, c
    do c = 1, size(work%n0)   ! no matmul: its result would be a heap temporary
      work%normal(c) = work%n0(c)
      do i = 1, self%ns
        work%normal(c) = work%normal(c) + work%g_mat(c, i)*qdd(i)
      end do
    end do
  end subroutine affine_normal_forces

  !> The complete state at (t, q, q'): accelerations, cut forces, every law's
  !> loads and power, every contact's normal force, the record-only elements'
  !> outputs; returns the inverse-dynamics residual max |Q_bar| (zero up to
  !> rounding when everything is consistent).
  module procedure evaluate
    real(wp) :: qdd(self%ns)
    integer :: c, reused
    residual = huge(1.0_wp)
    reused = work%dynamics_reused
    call self%dynamics(work, t, q, qd, qdd, status)
    if (status%ok()) call self%record_pass(work, status)   ! at q: a reused dynamics left the positions there
    if (.not. status%ok()) return
    ! a reused dynamics has just set these velocities; a computed one overwrote them
    if (work%dynamics_reused == reused) call self%set_velocities(work, qd)
    call self%set_accelerations(work, qdd)
    call self%inverse_dynamics(work, .true., .true., LOADS_ALL)
    residual = maxval(abs(work%gq))
    call self%normal_forces(work, work%lambda, work%work_c)
    work%normal_force(:) = work%work_c
  end procedure evaluate
end submodule kinetostatics_mechanism_dynamics

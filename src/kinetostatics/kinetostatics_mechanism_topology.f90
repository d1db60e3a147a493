!> The mechanism's topology (kinetostatics_mechanism): building it
!> (frames, scalars, elements, loops, rate constraints, contacts, laws) and
!> finalize, which checks the structure, finds the speeds, the domain
!> edges, the closure's blocks and the frames whose twists the dynamics
!> keeps, and sizes the work arrays.
submodule (kinetostatics_mechanism) kinetostatics_mechanism_topology
  implicit none (type, external)

  integer :: models_stamped = 0   ! stamps given so far (find_workspace_dims)

contains

  !> Adds a frame and returns its index (the ground, index 1, exists from the start).
  module procedure add_frame
    type(frame_state_t) :: empty
    call ensure_ground(self)
    self%frames = [self%frames, empty]
    self%frame_names = [character(len=32) :: self%frame_names, name]
    self%n_frames = self%n_frames + 1
    k = self%n_frames
  end procedure add_frame

  subroutine ensure_ground(self)
    class(mechanism_t), intent(inout) :: self
    if (self%n_frames > 0) return
    allocate (self%frames(1), self%frame_names(1), self%scalars(0), self%scalar_names(0), self%role(0))
    allocate (self%elements(0), self%loops(0), self%contacts(0), self%laws(0), self%rate_constraints(0))
    self%frame_names(1) = 'ground'
    self%n_frames = 1
  end subroutine ensure_ground

  !> Adds a scalar (joint variable or measurement) with value `value`.
  module procedure add_scalar
    type(scalar_state_t) :: s
    call ensure_ground(self)
    if (present(value)) s%q = value
    self%scalars = [self%scalars, s]
    self%scalar_names = [character(len=32) :: self%scalar_names, name]
    self%role = [self%role, ROLE_FIXED]
    self%n_scalars = self%n_scalars + 1
    k = self%n_scalars
  end procedure add_scalar

  module procedure add_element
    type(element_box_t), allocatable :: grown(:)
    integer :: k
    call ensure_ground(self)
    allocate (grown(self%n_elements + 1))
    do k = 1, self%n_elements
      call move_alloc(self%elements(k)%e, grown(k)%e)
    end do
    allocate (grown(self%n_elements + 1)%e, source=e)
    call move_alloc(grown, self%elements)
    self%n_elements = self%n_elements + 1
  end procedure add_element

  !> A closed loop: its closure measurements (scalar indices, required values)
  !> and as many dependent coordinates.
  module procedure add_loop
    type(loop_t) :: loop
    if (size(measurements) /= size(dependents) .or. size(targets) /= size(measurements)) then
      call set_status(status, STATUS_INVALID_INPUT, 'loop '''//name//''': needs as many closure '// &
                      'measurements (and targets) as dependent coordinates')
      return
    end if
    loop%name = name
    loop%measurements = measurements
    loop%targets = targets
    loop%dependents = dependents
    self%loops = [self%loops, loop]
    self%role(measurements) = ROLE_MEASURE
    self%role(dependents) = ROLE_BETA
  end procedure add_loop

  !> The branch of loop `name`: the z axes of frames frame_1 and frame_2 must
  !> point against each other (z_1 . z_2 < 0), as the normals of two surfaces
  !> in contact do; conditions like g4, g5 of (3.86) also hold on the branch
  !> with parallel normals. A closure that lands there fails with
  !> STATUS_DOMAIN (at the start: bad input; in a run: the step is shortened).
  module procedure set_loop_branch
    integer :: k
    do k = 1, size(self%loops)
      if (self%loops(k)%name == name) then
        self%loops(k)%antiparallel = [frame_1, frame_2]
        return
      end if
    end do
    call set_status(status, STATUS_INVALID_INPUT, 'set_loop_branch: there is no loop '''//name//'''')
  end procedure set_loop_branch

  !> A velocity-level constraint: the rates of the scalars `outputs` (written by
  !> constraint elements) must vanish; the rates of the coordinates
  !> `dependents` (as many, among set_coordinates) follow from that.
  module procedure add_rate_constraint
    type(rate_constraint_t) :: c
    call ensure_ground(self)
    if (size(outputs) /= size(dependents)) then
      call set_status(status, STATUS_INVALID_INPUT, 'rate constraint '''//name//''': needs as many '// &
                      'outputs as coordinates with dependent rates')
      return
    end if
    c%name = name
    c%outputs = outputs
    c%dependents = dependents
    self%rate_constraints = [self%rate_constraints, c]
    self%role(outputs) = ROLE_MEASURE
  end procedure add_rate_constraint

  !> A scalar (e.g. a measurement that watches a velocity-level contact's
  !> drift) recorded with every state, in `units`.
  module procedure add_monitor
    if (.not. allocated(self%monitors)) allocate (self%monitors(0), self%monitor_units(0))
    self%monitors = [self%monitors, scalar]
    self%monitor_units = [character(len=8) :: self%monitor_units, units]
  end procedure add_monitor

  !> Coordinates (among set_coordinates) whose rates an element writes in its
  !> velocity pass: integrated, but neither speeds nor solved.
  module procedure set_kinematic
    self%kinematic = scalars
  end procedure set_kinematic

  !> A contact between the body carrying frame_a (1: the ground) and the body
  !> carrying frame_b at the contact-point frame point_frame (origin at the
  !> contact point, z along the surface normal); returns its index. The
  !> normal force is N = -normal_sign z_F . f_F at frame F = normal_frame
  !> (default: point_frame), or, if normal_measurement (a closure measurement's
  !> scalar index) is given, N = normal_sign lambda of that measurement.
  !> normal_sign (+1 or -1, default +1) makes N positive while the bodies
  !> press on each other; n = normal_sign z points from A into B. One-sided
  !> (default): N falling through zero is the lift-off event.
  module procedure add_contact
    type(contact_t) :: c
    call ensure_ground(self)
    c%name = name
    c%frame_a = frame_a
    c%frame_b = frame_b
    c%point_frame = point_frame
    c%normal_frame = point_frame
    if (present(normal_sign)) c%normal_sign = normal_sign
    if (present(normal_frame)) c%normal_frame = normal_frame
    if (present(normal_measurement)) then
      c%normal_rule = NORMAL_CUT_FORCE
      c%normal_measurement = normal_measurement
    end if
    if (present(one_sided)) c%one_sided = one_sided
    self%contacts = [self%contacts, c]
    k = size(self%contacts)
  end procedure add_contact

  !> Adds a force law (a copy of `law`); its index is n_laws afterwards.
  module procedure add_law
    type(force_law_box_t), allocatable :: grown(:)
    integer :: k
    call ensure_ground(self)
    allocate (grown(self%n_laws + 1))
    do k = 1, self%n_laws
      call move_alloc(self%laws(k)%law, grown(k)%law)
    end do
    allocate (grown(self%n_laws + 1)%law, source=law)
    call move_alloc(grown, self%laws)
    self%n_laws = self%n_laws + 1
  end procedure add_law

  module procedure set_coordinates
    self%q = q
    self%role(q) = ROLE_Q
  end procedure set_coordinates

  module procedure frame_index
    do k = 1, self%n_frames
      if (self%frame_names(k) == name) return
    end do
    k = 0
  end procedure frame_index

  module procedure scalar_index
    do k = 1, self%n_scalars
      if (self%scalar_names(k) == name) return
    end do
    k = 0
  end procedure scalar_index

  module procedure contact_index
    do k = 1, size(self%contacts)
      if (self%contacts(k)%name == name) return
    end do
    k = 0
  end procedure contact_index

  module procedure law_index
    do k = 1, self%n_laws
      if (self%laws(k)%law%name == name) return
    end do
    k = 0
  end procedure law_index

  !> Checks the structure and finds what the computations need of it (their
  !> results and work arrays: prepare_workspace).
  module procedure finalize
    integer :: k, ns, nr
    if (.not. status%ok()) return
    call ensure_ground(self)
    if (.not. allocated(self%q)) allocate (self%q(0))
    self%f = size(self%q)
    if (self%f < 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'mechanism: no generalized coordinates')
      return
    end if
    allocate (self%beta(0), self%closure(0), self%target(0))
    do k = 1, size(self%loops)
      self%beta = [self%beta, self%loops(k)%dependents]
      self%closure = [self%closure, self%loops(k)%measurements]
      self%target = [self%target, self%loops(k)%targets]
    end do
    self%r = size(self%beta)
    call find_speeds(self, status)
    if (.not. status%ok()) return
    call check_contacts(self, status)
    if (status%ok()) call check_laws(self, status)
    if (.not. status%ok()) return
    call find_edges(self)
    call find_closure_blocks(self)
    call check_record_only(self, status)
    if (.not. status%ok()) return

    ! scaled laws and the contacts whose normal forces the block system solves for
    allocate (self%scaled_laws(0), self%block_contact(0))
    do k = 1, self%n_laws
      if (.not. self%laws(k)%law%scaled) cycle
      self%scaled_laws = [self%scaled_laws, k]
      if (.not. any(self%block_contact == self%laws(k)%law%contact)) &
        self%block_contact = [self%block_contact, self%laws(k)%law%contact]
    end do
    ns = size(self%scaled_laws)
    allocate (self%block_row(ns))
    do k = 1, ns
      self%block_row(k) = findloc(self%block_contact, self%laws(self%scaled_laws(k))%law%contact, dim=1)
    end do
    call find_recursion(self)
    allocate (self%law_root_start(self%n_laws + 1))
    nr = 0
    do k = 1, self%n_laws
      self%law_root_start(k) = nr + 1
      nr = nr + self%laws(k)%law%root_count()
    end do
    self%law_root_start(self%n_laws + 1) = nr + 1

    call find_workspace_dims(self)
    self%ready = .true.
  end procedure finalize

  !> Every size a workspace depends on and a stamp of this model, new at
  !> every finalize and set_blocked (prepare_workspace): a workspace holds the
  !> state of one model (its copies share the stamp).
  subroutine find_workspace_dims(self)
    class(mechanism_t), intent(inout) :: self
    models_stamped = models_stamped + 1
    self%workspace_dims = [self%f, self%ns, self%r, self%nd, size(self%contacts), self%n_laws, &
                           size(self%block_contact), size(self%tracked), size(self%moving_unknowns), &
                           size(self%scaled_laws), self%law_root_start(self%n_laws + 1) - 1, models_stamped]
  end subroutine find_workspace_dims

  !> The closure in blocks with partial passes (blocked, the default) or as
  !> one block with full passes (the unblocked computation, for comparison);
  !> after finalize. A new model: a workspace starts again from its state
  !> (prepare_workspace), the closure cold.
  module procedure set_blocked
    self%blocked = blocked
    if (.not. self%ready) return
    call find_closure_blocks(self)
    call find_recursion(self)
    call find_workspace_dims(self)
  end procedure set_blocked

  !> The equations of motion by the tree recursion where the mechanism is a
  !> chain or tree of at least from_bodies bodies (kinetostatics_tree; 2: any
  !> tree), or always by the dense mass matrix (0: for comparison); before
  !> or after finalize. A new model, as for set_blocked.
  module procedure set_recursion
    self%recursion_bodies = from_bodies
    if (.not. self%ready) return
    call find_recursion(self)
    call find_workspace_dims(self)
  end procedure set_recursion

  !> The tree of the bodies if the recursion is asked for (recursion_bodies
  !> bodies or more: below, the dense path costs less) and covers the
  !> mechanism: no scaled laws (their block system needs M) and no
  !> kinematic coordinates (velocity-level contacts: not compared), else none.
  subroutine find_recursion(self)
    class(mechanism_t), intent(inout) :: self
    integer :: k
    if (self%recursion_bodies > 0 .and. size(self%tracked) >= self%recursion_bodies .and. &
        size(self%scaled_laws) == 0 .and. size(self%kinematic) == 0) then
      call find_tree(self%tree, self%reach, self%blocks, self%n_frames, self%n_scalars, self%q(self%speeds), &
                     self%unknowns, self%rows, self%tracked, self%masses, &
                     [(self%elements(self%masses(k))%e%mass_frame(), k = 1, size(self%masses))])
    else
      self%tree%active = .false.
      self%tree%n_bodies = 0
    end if
  end subroutine find_recursion

  !> Sizes the workspace for this mechanism (kinetostatics_mechanism_workspace)
  !> and gives it the model's state to start from: on its first use and again
  !> only when the model changed (finalize, set_blocked, another mechanism).
  !> The model's frames, scalars, elements, closure blocks and laws (loads,
  !> switches; factors 1) as it holds them, the closure cold, no cached
  !> dynamics, no results (zero cut forces, rates, accelerations, normal
  !> forces and powers).
  module procedure prepare_workspace
    integer :: n, nc, nb, nt, nx, ns, nr, k
    if (all(work%dims == self%workspace_dims)) return
    n = self%ns
    nc = size(self%contacts)
    nb = size(self%block_contact)
    nt = size(self%tracked)
    nx = self%r + self%nd
    ns = size(self%scaled_laws)
    nr = self%law_root_start(self%n_laws + 1) - 1
    if (allocated(work%known_q)) then
      deallocate (work%lambda, work%mu, work%rates, work%qdd, work%mass, work%bias, work%normal, &
                  work%law_power, work%unit_power, work%law_roots, work%contact_states, work%gq, &
                  work%g_mat, work%p_mat, work%h_mat, work%laws, work%law_factor, work%normal_force)
      deallocate (work%known_q, work%known_s, work%known_active, work%work_r, work%work_x, work%x_r, &
                  work%start_r, work%res_r, work%recent_r, work%recent_q, &
                  work%work_f, work%work_c, work%chol, work%n0, work%block, &
                  work%block_rhs, work%signs, work%ipiv_block, work%twist, work%wrench, work%unknown_twist, &
                  work%nu, work%load_wrench)
    end if
    allocate (work%lambda(self%r), work%mu(self%nd), work%rates(self%f), work%qdd(n), work%mass(n, n), &
              work%bias(n), work%gq(n))
    allocate (work%contact_states(nc), work%normal(nc), work%law_power(self%n_laws), &
              work%unit_power(self%n_laws), work%law_roots(nr))
    allocate (work%g_mat(nc, n), work%p_mat(n, ns), work%h_mat(nc, ns))
    work%lambda = 0
    work%mu = 0
    work%rates = 0
    work%qdd = 0
    work%normal = 0
    work%law_power = 0
    work%law_roots = 1
    work%frames = self%frames
    work%scalars = self%scalars
    work%elements = self%elements
    work%blocks = self%blocks
    work%laws = self%laws
    allocate (work%law_factor(self%n_laws), work%normal_force(nc))
    work%law_factor = 1
    work%normal_force = 0
    work%warm = .false.
    work%converged = .false.
    allocate (work%known_q(self%f), work%known_s(n), work%known_active(self%n_laws))
    allocate (work%work_r(self%r), work%work_x(nx), work%x_r(self%r), work%start_r(self%r), work%res_r(self%r), &
              work%work_f(n), work%work_c(nc))
    allocate (work%recent_r(self%r, recent_solutions), work%recent_q(self%f, recent_solutions))
    work%recent_charts = -1
    work%recent_next = 1
    work%solve_failed = .false.
    allocate (work%chol(n, n), work%n0(nc), work%block(n + nb, n + nb), work%block_rhs(n + nb), work%signs(nb), &
              work%ipiv_block(n + nb))
    allocate (work%twist(6, nt, n), work%wrench(6, nt, n), work%unknown_twist(6, nt, size(self%moving_unknowns)), &
              work%nu(6, nt, nc), work%load_wrench(6, nt))
    call work%tree%size_for(self%tree, n)
    do k = 1, self%r
      work%start_r(k) = work%scalars(self%beta(k))%q
    end do
    work%known_evaluation = -1
    work%dims = self%workspace_dims
  end procedure prepare_workspace

  !> The closure's blocks: x = [beta; sigma], rows [g; c], one group per loop
  !> and per rate constraint.
  subroutine find_closure_blocks(self)
    class(mechanism_t), intent(inout) :: self
    integer :: group_start(size(self%loops) + size(self%rate_constraints) + 1), k, g
    self%unknowns = [self%beta, self%sigma]
    self%rows = [self%closure, self%rate_outputs]
    g = 1
    group_start(1) = 1
    do k = 1, size(self%loops)
      g = g + 1
      group_start(g) = group_start(g - 1) + size(self%loops(k)%dependents)
    end do
    do k = 1, size(self%rate_constraints)
      g = g + 1
      group_start(g) = group_start(g - 1) + size(self%rate_constraints(k)%dependents)
    end do
    call find_element_links(self%elements, self%n_frames, self%n_scalars, self%reach)
    if (self%blocked) then
      self%beta_pass = downstream_of(self%reach, self%beta, self%n_frames, self%n_scalars, self%n_elements)
      self%unknowns_pass = downstream_of(self%reach, self%unknowns, self%n_frames, self%n_scalars, self%n_elements)
    else
      self%beta_pass = [(k, k = 1, self%n_elements)]
      self%unknowns_pass = self%beta_pass
    end if
    if (self%reach%known) self%beta_pass = pack(self%beta_pass, &   ! check_record_only
      [(.not. self%elements(self%beta_pass(k))%e%record_only, k = 1, size(self%beta_pass))])
    ! a surface joint that beta does not reach is evaluated once per closure
    ! (its first pass), and the velocities after it need its whole geometry:
    ! eager there, the lazy order-1 evaluation would be repeated at order 3
    ! (kinetostatics_surface_joint; the same numbers either way)
    if (self%r > 0) then
      do k = 1, self%n_elements
        if (any(self%beta_pass == k)) cycle
        call self%elements(k)%e%set_eager()
      end do
    end if
    call build_closure_blocks(self%blocks, self%elements, self%reach, self%n_frames, self%n_scalars, &
                              self%unknowns, self%rows, self%r, group_start, self%blocked)
    call find_mass_twists(self)
  end subroutine find_closure_blocks

  !> The frames whose partial twists `dynamics` keeps (every mass element's,
  !> and both frames of each scaled law's contact), the contacts whose normal
  !> force is the force on a frame, and the pass lists
  !> (kinetostatics_closure_blocks, build_mass_columns).
  subroutine find_mass_twists(self)
    class(mechanism_t), intent(inout) :: self
    logical :: keep(self%n_frames)
    integer :: k, c, nt, nx
    keep = .false.
    self%masses = [integer ::]
    do k = 1, self%n_elements
      if (self%elements(k)%e%mass_frame() == 0) cycle
      self%masses = [self%masses, k]
      keep(self%elements(k)%e%mass_frame()) = .true.
    end do
    do k = 1, self%n_laws
      c = self%laws(k)%law%contact
      if (.not. self%laws(k)%law%scaled .or. c < 1) cycle
      keep([self%contacts(c)%frame_a, self%contacts(c)%frame_b]) = .true.
    end do
    keep(1) = .false.   ! the ground never moves
    self%tracked = pack([(k, k = 1, self%n_frames)], keep)
    nt = size(self%tracked)
    self%tracked_slot = [(0, k = 1, self%n_frames)]
    self%tracked_slot(self%tracked) = [(k, k = 1, nt)]
    self%mass_slot = [integer ::]
    do k = 1, size(self%masses)
      self%mass_slot = [self%mass_slot, self%tracked_slot(self%elements(self%masses(k))%e%mass_frame())]
    end do
    self%normal_contacts = pack([(c, c = 1, size(self%contacts))], &
                                self%contacts%normal_rule == NORMAL_FRAME_FORCE)
    call self%blocks%build_mass_columns(self%reach, self%n_frames, self%n_scalars, self%q(self%speeds), &
                                        self%unknowns, self%rows, self%tracked, &
                                        self%contacts(self%normal_contacts)%normal_frame, self%blocked)
    self%twist_route = self%reach%known
    self%velocity_columns = self%blocks%mass_blocked .and. size(self%blocks%touched) == 0
    if (self%velocity_columns) call build_velocity_clears(self)
    nx = self%r + self%nd
    self%moving_unknowns = pack([(k, k = 1, nx)], self%blocks%unknown_pass_start(2:nx + 1) > &
                                                  self%blocks%unknown_pass_start(1:nx))
  end subroutine find_mass_twists

  !> Dependent rates, constraint outputs and kinematic coordinates must be
  !> coordinates; the speeds are the other coordinates.
  subroutine find_speeds(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    logical :: free(self%f)
    if (.not. allocated(self%kinematic)) allocate (self%kinematic(0))
    if (.not. allocated(self%monitors)) allocate (self%monitors(0), self%monitor_units(0))
    allocate (self%sigma(0), self%rate_outputs(0))
    do k = 1, size(self%rate_constraints)
      self%sigma = [self%sigma, self%rate_constraints(k)%dependents]
      self%rate_outputs = [self%rate_outputs, self%rate_constraints(k)%outputs]
    end do
    self%nd = size(self%sigma)
    free = .true.
    do k = 1, self%nd
      if (.not. any(self%q == self%sigma(k))) then
        call set_status(status, STATUS_INVALID_INPUT, 'rate constraint: '''//trim(self%scalar_names(self%sigma(k)))// &
                        ''' must be a generalized coordinate to have a dependent rate')
        return
      end if
      free(findloc(self%q, self%sigma(k), dim=1)) = .false.
    end do
    do k = 1, size(self%kinematic)
      if (.not. any(self%q == self%kinematic(k))) then
        call set_status(status, STATUS_INVALID_INPUT, 'kinematic coordinate '''// &
                        trim(self%scalar_names(self%kinematic(k)))//''' must be a generalized coordinate')
        return
      end if
      free(findloc(self%q, self%kinematic(k), dim=1)) = .false.
    end do
    self%speeds = pack([(k, k = 1, self%f)], free)
    self%ns = size(self%speeds)
    if (self%ns < 1) call set_status(status, STATUS_INVALID_INPUT, 'mechanism: no independent speeds '// &
      '(every coordinate''s rate is constrained or kinematic)')
  end subroutine find_speeds

  subroutine check_contacts(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        if (.not. all([c%frame_a, c%frame_b, c%point_frame, c%normal_frame] >= 1 .and. &
                      [c%frame_a, c%frame_b, c%point_frame, c%normal_frame] <= self%n_frames)) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': a frame index is not '// &
                          'a frame of the mechanism')
        else if (c%frame_a == c%frame_b) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': the two bodies must '// &
                          'be different (frame_a = frame_b)')
        else if (abs(c%normal_sign) /= 1) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': normal_sign must be +1 or -1')
        else if (c%normal_rule == NORMAL_CUT_FORCE) then
          c%normal_row = findloc(self%closure, c%normal_measurement, dim=1)
          if (c%normal_row == 0) call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name// &
            ''': its normal force must be the cut force of a closure measurement of a loop')
        end if
      end associate
      if (.not. status%ok()) return
    end do
  end subroutine check_contacts

  subroutine check_laws(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%n_laws
      associate (law => self%laws(k)%law)
        if (.not. allocated(law%name)) law%name = 'law'
        if (.not. allocated(law%loads)) then
          call set_status(status, STATUS_INVALID_INPUT, 'force law '''//law%name//''' has no loads '// &
                          '(its constructor must allocate them)')
        else if (law%contact < 0 .or. law%contact > size(self%contacts)) then
          call set_status(status, STATUS_INVALID_INPUT, 'force law '''//law%name//''': contact index '// &
                          'out of range')
        else if (law%scaled .and. law%contact == 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'force law '''//law%name//''' scales with a '// &
                          'normal force but names no contact')
        end if
      end associate
      if (.not. status%ok()) return
    end do
  end subroutine check_laws

  !> The finite, non-periodic edges of every element's domain (element_t's domain_edges).
  subroutine find_edges(self)
    class(mechanism_t), intent(inout) :: self
    type(domain_edge_t), allocatable :: edges(:)
    integer :: k, j
    allocate (self%edges(0))
    do k = 1, self%n_elements
      call self%elements(k)%e%domain_edges(edges)
      self%edges = [self%edges, (surface_edge_t(edges(j), k), j = 1, size(edges))]
    end do
  end subroutine find_edges

  !> Only records may read the outputs of a record-only element (element_t):
  !> no other element, loop, rate constraint, coordinate or contact (force
  !> laws name what they read in their own terms: they must not read them
  !> either). A mechanism whose data flow is not known (an element of
  !> unknown links) evaluates them in every position pass.
  subroutine check_record_only(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    logical :: read_frame(self%n_frames), read_scalar(self%n_scalars)
    integer :: k, i
    if (.not. self%reach%known) then
      do k = 1, self%n_elements
        self%elements(k)%e%record_only = .false.
      end do
      return
    end if
    read_frame = .false.
    read_scalar = .false.
    do k = 1, self%n_elements
      if (self%elements(k)%e%record_only) cycle
      associate (r => self%reach)
        read_frame(r%frame_in(r%frame_in_start(k):r%frame_in_start(k + 1) - 1)) = .true.
        read_scalar(r%scalar_in(r%scalar_in_start(k):r%scalar_in_start(k + 1) - 1)) = .true.
      end associate
    end do
    read_scalar([self%closure, self%rate_outputs, self%q]) = .true.
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        read_frame([c%frame_a, c%frame_b, c%point_frame, c%normal_frame]) = .true.
        if (c%normal_measurement > 0) read_scalar(c%normal_measurement) = .true.
      end associate
    end do
    do k = 1, self%n_elements
      if (.not. self%elements(k)%e%record_only) cycle
      associate (r => self%reach)
        do i = r%frame_out_start(k), r%frame_out_start(k + 1) - 1
          if (read_frame(r%frame_out(i))) call refuse('frame '''//trim(self%frame_names(r%frame_out(i)))//'''')
        end do
        do i = r%scalar_out_start(k), r%scalar_out_start(k + 1) - 1
          if (read_scalar(r%scalar_out(i))) call refuse('scalar '''//trim(self%scalar_names(r%scalar_out(i)))//'''')
        end do
      end associate
      if (.not. status%ok()) return
    end do
  contains
    subroutine refuse(what)
      character(len=*), intent(in) :: what
      if (status%ok()) call set_status(status, STATUS_INVALID_INPUT, 'element '''//self%elements(k)%e%name// &
        ''' is record-only, but its output '//what//' is read by the mechanism (another element, a loop, '// &
        'a rate constraint, a coordinate or a contact)')
    end subroutine refuse
  end subroutine check_record_only

  !> The velocity columns run from the last speed to the first: before
  !> column i the outputs of the elements pass i + 1 ran and pass i does not
  !> go back to rest (the others pass i overwrites or never moved). For a
  !> chain, whose speeds' passes grow towards its root, there are none.
  subroutine build_velocity_clears(self)
    class(mechanism_t), intent(inout) :: self
    integer :: i, p
    integer, allocatable :: clear(:), start(:)
    allocate (clear(0), start(self%ns + 1))
    associate (first => self%blocks%mass_pass_start, pass => self%blocks%mass_pass)
      do i = 1, self%ns
        start(i) = size(clear) + 1
        if (i == self%ns) cycle
        do p = first(i + 1), first(i + 2) - 1
          if (.not. any(pass(first(i):first(i + 1) - 1) == pass(p))) clear = [clear, pass(p)]
        end do
      end do
    end associate
    start(self%ns + 1) = size(clear) + 1
    self%velocity_clear = clear
    self%velocity_clear_start = start
  end subroutine build_velocity_clears
end submodule kinetostatics_mechanism_topology

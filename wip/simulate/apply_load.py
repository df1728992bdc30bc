p='/work/wt-workflow/src/physics/drive_row.h'; s=open(p).read()
s=s.replace('FrameResult step_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target);',
 '''// `load`: a constant external torque (force) on the joint, integrated into the velocity
// before each solve as PhysX integrates external forces (a payload, gravity).
FrameResult step_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,
                       double load = 0);''')
s=s.replace('FrameResult explicit_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target);',
 '''FrameResult explicit_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,
                           double load = 0);''')
open(p,'w').write(s)
p='/work/wt-workflow/src/physics/drive_row.cpp'; s=open(p).read()
s=s.replace('FrameResult step_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target) {',
 'FrameResult step_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,\n                       double load) {')
s=s.replace('''    for (int s = 0; s < row.substeps; ++s) {
      solve(s * row.h);''','''    for (int s = 0; s < row.substeps; ++s) {
      state.velocity += load * row.h * row.response;
      solve(s * row.h);''')
s=s.replace('''    for (int i = 0; i < row.iterations; ++i) {
      solve(0.0);''','''    state.velocity += load * row.dt * row.response;
    for (int i = 0; i < row.iterations; ++i) {
      solve(0.0);''')
s=s.replace('FrameResult explicit_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target) {',
 'FrameResult explicit_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,\n                           double load) {')
s=s.replace('''    state.velocity += row.h * force * row.response;''','''    state.velocity += row.h * (force + load) * row.response;''')
open(p,'w').write(s)

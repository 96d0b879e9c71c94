//! Step-response metrics with the definitions of python-control `step_info` / MATLAB `stepinfo`.

### rlc

rlc-axis-current = 电流 i
rlc-axis-voltage = 电容电压 v_C
rlc-envelope = 包络线
rlc-series-critical = 临界 R = { $resistance }
rlc-schematic = t = { $time } 时的 RLC 串联回路：电流 { $current }，电容电压 { $voltage }。
rlc-describe-current-undamped = R = { $resistance }，无阻尼（无损 LC 回路）：电流以 ω₀ = { $frequency } 持续振荡，在 ±{ $bound } 之间变化（每半个周期，全部能量转入电感后又返回）。
rlc-describe-voltage-undamped = R = { $resistance }，无阻尼（无损 LC 回路）：电容电压以 ω₀ = { $frequency } 在 +{ $voltage } 与 −{ $voltage } 之间持续振荡。
rlc-describe-current-underdamped = R = { $resistance }，低于临界电阻 { $critical }，欠阻尼：电流以 ω_d = { $frequency } 振荡（Q = { $q }），按 e^(−αt) 衰减，α = { $alpha }；电流始终不超过 { $bound }。
rlc-describe-voltage-underdamped = R = { $resistance }，低于临界电阻 { $critical }，欠阻尼：电容电压{ $reversal ->
        [slight] 仅轻微反向（最多为 V₀ 的 { $rebound }，仍在误差带内）
        [count] { $crossings ->
            [1] 在稳定前改变一次极性
           *[other] 在稳定前改变 { $crossings } 次极性
        }
       *[never] 从不改变极性
    }，{ $settles ->
        [yes] 并在 { $time } 后保持在 V₀ 的 5 % 以内
       *[no] 且始终不稳定
    }。
rlc-describe-current-critical = R = { $resistance }，等于临界电阻，临界阻尼：只有一个电流脉冲（为负，电容正在放电），回到零而不反向；电流始终不超过 { $bound }。
rlc-describe-voltage-critical = R = { $resistance }，等于临界电阻，临界阻尼：电容以最快速度放电且不反向；{ $settles ->
        [yes] 电压在 { $time } 后保持在 V₀ 的 5 % 以内
       *[no] 电压始终不稳定
    }。
rlc-describe-current-overdamped = R = { $resistance }，高于临界电阻 { $critical }，过阻尼：一个缓慢的电流脉冲（为负，电容正在放电），不反向，慢时间常数为 { $time }。
rlc-describe-voltage-overdamped = R = { $resistance }，高于临界电阻 { $critical }，过阻尼：电容缓慢放电且不反向；{ $settles ->
        [yes] 电压在 { $time } 后保持在 V₀ 的 5 % 以内
       *[no] 电压始终不稳定
    }。
rlc-title = RLC 串联电路
rlc-summary = 充电至 V₀ 的电容在 t = 0 时接入含电感和电阻的回路。电荷 q 满足与弹簧上的质量相同的方程：L 相当于质量，R 相当于阻尼器，1/C 相当于弹簧。当 R 小于临界电阻 2√(L/C) 时，能量在 C 与 L 之间来回转移，电流以 ω_d 振荡，并按 e^(−αt) 衰减，α = R/(2L)；当 R = 2√(L/C) 时，电容以最快速度放电且不反向；R 再大，放电又变慢。Q = 1/(2ζ) 衡量振荡的多少，R/L 是电流谐振的半功率带宽：在正弦电压激励下，|I|² 保持在峰值一半以上的频带宽度恰为 R/L rad/s，与 R 无关。电容放电时电流为负（i = dq/dt）。
rlc-param-R = 电阻
rlc-param-L = 电感
rlc-param-C = 电容
rlc-param-V0 = 电容初始电压
rlc-readout-regime = 阻尼状态
rlc-readout-w0 = 谐振角频率 ω₀ = 1/√(LC)
rlc-readout-f0 = 谐振频率 f₀
rlc-readout-alpha = 衰减率 α = R/(2L)
rlc-readout-zeta = 阻尼比 ζ
rlc-readout-Q = 品质因数 Q = 1/(2ζ)
rlc-readout-bandwidth = 电流谐振的半功率带宽 Δω = R/L
rlc-readout-R-crit = 临界电阻 2√(L/C)
rlc-readout-wd = 振荡角频率 ω_d
rlc-readout-settling-time = v_C 进入 V₀ 的 5 % 以内所需时间
rlc-plot-current = 电流 i(t)
rlc-plot-voltage = 电容电压 v_C(t)
rlc-preset-1 = 无损 LC，R = 0
rlc-preset-2 = 振荡，R = 2 Ω
rlc-preset-3 = 欠阻尼，R = 5 Ω
rlc-preset-4 = 临界阻尼，R = 10 Ω
rlc-preset-5 = 过阻尼，R = 20 Ω


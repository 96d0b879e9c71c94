## 示意图

schematic-title = 示意图
schematic-circuit = 电路
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

### analogy

analogy-axis-response = 归一化响应
analogy-axis-energy = 能量
analogy-series-x = x/x₀ 质量
analogy-series-q = q/q₀ 电路
analogy-series-v = v/(x₀ωₙ) 质量
analogy-series-i = i/(q₀ω₀) 电路
analogy-series-spring = ½kx² 弹簧
analogy-series-capacitor = ½q²/C 电容
analogy-series-mass = ½mv² 质量
analogy-series-inductor = ½Li² 电感
analogy-series-total-mass = 总能量（机械）
analogy-series-total-circuit = 总能量（电路）
analogy-caption-mechanical = 机械
analogy-caption-electrical = 电气
analogy-schematic-title = 机械与电气的孪生系统
analogy-describe-responses = { $regime }（ζ = { $zeta }）：机械的 x/x₀ 与电气的 q/q₀ 重合，速度 v/(x₀ωₙ) 与电流 i/(q₀ω₀) 也重合（{ $same ->
        [exact] 直到最后一位都相同
       *[close] 最大差值 { $difference }
    }）；{ $motion ->
        [decaying] 两者都以 ω_d = { $frequency } 振荡，并以时间常数 1/(ζωₙ) = { $time } 衰减
        [lasting] 两者都以 ω₀ = ωₙ = { $frequency } 持续振荡
       *[creeping] 两者都缓慢回到静止，不发生振荡
    }。
analogy-describe-energy = t = 0 时，全部能量 { $energy } 储存在弹簧中，同样也储存在电容中。{ $exchange ->
        [swings] 能量转入质量（电感），同一时刻最多 { $peak }，然后返回，每个周期两次
       *[passes] 不发生振荡，最多有 { $peak } 经过质量（电感）
    }；{ $loss ->
        [none] 没有阻尼器（电阻），{ $time } 后能量仍全部保留
       *[heat] 阻尼器 c（电阻 R）将其转化为热，{ $time } 后剩余 { $left }（{ $percent }）
    }。机械曲线与电气曲线重合。
analogy-schematic = t = { $time } 时：质量位移 { $displacement }，速度 { $velocity }；电容电荷 { $charge }，电流 { $current }。数值相同，只是单位不同。
analogy-title = 一个方程，两个系统
analogy-summary = 由弹簧和阻尼器支承的质量，与电感–电阻–电容串联回路，满足同一个二阶方程。在力–电压类比中，质量 m ↔ 电感 L，阻尼 c ↔ 电阻 R，刚度 k ↔ 1/C，力 F ↔ 电压 E，位移 x ↔ 电荷 q（因此速度 ↔ 电流）。这里电路取与机械系统相同的数值（L 以 H 计 = m 以 kg 计，R 以 Ω 计 = c 以 N·s/m 计，1/C 以 1/F 计 = k 以 N/m 计，q₀ 以 C 计 = x₀ 以 m 计），两者都从静止释放：移动任一滑块，两个系统随之一起变化，它们的归一化响应始终是同一条曲线，能量在弹簧与质量之间的往返与在电容与电感之间完全相同。
analogy-param-m = 质量（≙ 电感 L）
analogy-param-c = 阻尼（≙ 电阻 R）
analogy-param-k = 弹簧刚度（≙ 1/C）
analogy-param-x0 = 初始位移（≙ 电荷 q₀）
analogy-readout-m = 质量 m
analogy-readout-L = 电感 L（≙ 质量 m）
analogy-readout-c = 阻尼 c
analogy-readout-R = 电阻 R（≙ 阻尼 c）
analogy-readout-k = 弹簧刚度 k
analogy-readout-elastance = 倒电容 1/C（≙ k）
analogy-readout-compliance = 柔度 1/k（≙ C）
analogy-readout-C = 电容 C（≙ 1/k）
analogy-readout-x0 = 初始位移 x₀
analogy-readout-q0 = 初始电荷 q₀（≙ x₀）
analogy-readout-wn = 固有频率 ωₙ = √(k/m)
analogy-readout-w0 = 谐振角频率 ω₀ = 1/√(LC)（≙ ωₙ）
analogy-readout-zeta = 阻尼比 ζ（两者）
analogy-readout-regime = 阻尼状态（两者）
analogy-readout-Q = 品质因数 Q（两者）
analogy-readout-energy = 储存能量 ½kx₀² = ½q₀²/C
analogy-plot-responses = 两个系统的归一化响应
analogy-plot-energy = 能量交换
analogy-preset-1 = 无摩擦弹簧 ↔ LC 振荡回路（c = R = 0）
analogy-preset-2 = 轻阻尼 ζ = 0.05
analogy-preset-3 = 临界阻尼 ζ = 1（c = 2√(mk)，R = 2√(L/C)）
analogy-preset-4 = 过阻尼 ζ = 2
analogy-preset-5 = 重而软：m = 4 kg ↔ L = 4 H，k = 25 N/m ↔ C = 40 mF
analogy-table-caption = 力–电压类比：对 a·y″ + b·y′ + c·y = f(t) 的两种解读，附两个系统的当前数值
analogy-table-column-1 = 在方程中的角色
analogy-table-column-2 = 机械
analogy-table-column-3 = 当前值
analogy-table-column-4 = 电气
analogy-table-column-5 = 当前值
analogy-table-inertia-1 = 惯性 a
analogy-table-inertia-2 = 质量 m [kg]
analogy-table-inertia-4 = 电感 L [H]
analogy-table-dissipation-1 = 耗散 b
analogy-table-dissipation-2 = 阻尼系数 c [N·s/m]
analogy-table-dissipation-4 = 电阻 R [Ω]
analogy-table-stiffness-1 = 刚度 c
analogy-table-stiffness-2 = 弹簧刚度 k [N/m]
analogy-table-stiffness-4 = 倒电容 1/C [1/F]
analogy-table-compliance-1 = 柔度 1/c
analogy-table-compliance-2 = 柔度 1/k [m/N]
analogy-table-compliance-4 = 电容 C [F]
analogy-table-drive-1 = 激励 f(t)
analogy-table-drive-2 = 力 F [N]
analogy-table-drive-3 = 0：从静止释放
analogy-table-drive-4 = 电压 E [V]
analogy-table-drive-5 = 0：回路中无电源
analogy-table-coordinate-1 = 坐标 y，初值 y₀
analogy-table-coordinate-2 = 位移 x，初值 x₀ [m]
analogy-table-coordinate-4 = 电荷 q，初值 q₀ [C]
analogy-table-rate-1 = 变化率 y′
analogy-table-rate-2 = 速度 v = ẋ [m/s]
analogy-table-rate-3 = 释放时为 0
analogy-table-rate-4 = 电流 i = q̇ [A]
analogy-table-rate-5 = 释放时为 0
analogy-table-natural-frequency-1 = 固有频率 √(c/a)
analogy-table-natural-frequency-2 = ωₙ = √(k/m) [rad/s]
analogy-table-natural-frequency-4 = ω₀ = 1/√(LC) [rad/s]
analogy-table-damping-ratio-1 = 阻尼比 ζ = b/(2√(ac))
analogy-table-damping-ratio-2 = ζ = c/(2√(mk))
analogy-table-damping-ratio-4 = ζ = (R/2)·√(C/L)
analogy-table-quality-factor-1 = 品质因数 Q = √(ac)/b
analogy-table-quality-factor-2 = Q = √(mk)/c
analogy-table-quality-factor-4 = Q = √(L/C)/R
analogy-table-potential-energy-1 = 由刚度储存
analogy-table-potential-energy-2 = 弹簧 ½kx²，释放时 ½kx₀² [J]
analogy-table-potential-energy-4 = 电容 ½q²/C，释放时 ½q₀²/C [J]
analogy-table-kinetic-energy-1 = 由惯性储存
analogy-table-kinetic-energy-2 = 质量 ½mv² [J]
analogy-table-kinetic-energy-3 = 释放时为 0
analogy-table-kinetic-energy-4 = 电感 ½Li² [J]
analogy-table-kinetic-energy-5 = 释放时为 0
analogy-table-power-lost-1 = 耗散功率
analogy-table-power-lost-2 = 阻尼器 c·v² [W]
analogy-table-power-lost-3 = 释放时为 0
analogy-table-power-lost-4 = 电阻 R·i² [W]
analogy-table-power-lost-5 = 释放时为 0

### universality

universality-axis-response = 归一化响应 y/y₀
universality-axis-time = 归一化时间 ωₙt
universality-series-critical = ζ = 1（临界阻尼），作为参照
universality-schematic-title = 系统 A 与系统 B
universality-match-off = 关闭
universality-match-on = 开启：B 与 A 的 ωₙ 和 ζ 相同
universality-match-too-light = 无法实现：保持其他参数不变时，B 的 ζ 不能低于 { $zeta_min }；A 的 ζ = { $zeta }
universality-match-out-of-range = 在滑块范围内无法实现：B 需要 { $symbol } = { $value }，超出 { $low } … { $high }
universality-match-impossible = 无法实现：A 没有固有频率
universality-describe-normalised = 从静止释放：A（{ $machine_a }，ζ = { $zeta_a }）{ $behaviour_a ->
        [forever] 持续振荡
        [dies-away] 振荡并逐渐衰减
        [fastest] 以最快速度返回且无超调
       *[creeps] 缓慢返回且无超调
    }；B（{ $machine_b }，ζ = { $zeta_b }）{ $behaviour_b ->
        [forever] 持续振荡
        [dies-away] 振荡并逐渐衰减
        [fastest] 以最快速度返回且无超调
       *[creeps] 缓慢返回且无超调
    }。{ $relation ->
        [coincide] 两条曲线重合（最大差值 { $gap }）。
       *[differ] 两条曲线最多相差 y₀ 的 { $gap }。
    }{ $thermal ->
        [yes] 双容热系统不会振荡：无论热容和热阻取何值，其 ζ 都大于 1。
       *[no] { "" }
    }
universality-describe-realtime = 实际时间，时长 { $window }：A 的时间尺度 1/ωₙ 为 { $scale_a }，B 的为 { $scale_b }；{ $pace ->
        [faster] B 的速度是 A 的 { $factor } 倍
        [slower] B 比 A 慢，速度仅为 A 的 1/{ $factor }
       *[same] B 与 A 完全同步
    }。
universality-schematic = t = { $time } 时：A（{ $machine_a }）：{ $coordinate_a } = { $value_a }；B（{ $machine_b }）：{ $coordinate_b } = { $value_b }。
universality-title = 一个方程，多种系统
universality-summary = 六种系统，一个方程 a·y″ + b·y′ + c·y = f(t)。为 A 和 B 各选一种系统，并用其自身的物理参数进行设置：每种系统给出各自的 a、b 和 c（单位各不相同），从而得到固有频率 ωₙ = √(c/a) 和阻尼比 ζ = b/(2√(ac))。从 y₀ 处静止释放时，系统的归一化响应 y/y₀ 随 ωₙt 的变化只取决于 ζ，因此 ζ 相同的系统画出同一条曲线。勾选“匹配”后，程序会求解 B 的调节参数，使其 ωₙ 和 ζ 与 A 相同：此时 B 的行为与 A 完全一致，每一秒都相同。双容热系统从不振荡：b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0，所以无论热容和热阻取何值，其 ζ > 1——热量没有惯性，不会越过平衡点。
universality-param-A = 系统 A
universality-param-A-mass-spring = 质量–弹簧–阻尼器
universality-param-A-rlc = RLC 串联电路
universality-param-A-u-tube = U 形管压力计
universality-param-A-servo = 直流电机位置伺服（PD 控制）
universality-param-A-storey = 受地面运动作用的建筑楼层
universality-param-A-thermal = 双容热系统
universality-param-A-m = 质量
universality-param-A-c = 阻尼系数
universality-param-A-k = 弹簧刚度
universality-param-A-L = 电感
universality-param-A-R = 电阻
universality-param-A-C = 电容
universality-param-A-len = 液柱长度
universality-param-A-bore = 管内径
universality-param-A-rho = 液体密度
universality-param-A-mu = 动力黏度
universality-param-A-J = 电机与负载的转动惯量
universality-param-A-Kt = 电机转矩常数
universality-param-A-Ra = 电枢电阻
universality-param-A-Kp = 比例增益
universality-param-A-Kd = 微分增益
universality-param-A-mf = 楼板质量
universality-param-A-h = 层高
universality-param-A-EI = 4 根柱中每根的抗弯刚度
universality-param-A-cf = 楼层阻尼系数
universality-param-A-C1 = 物体 1 的热容
universality-param-A-R1 = 热阻（物体 1 至环境）
universality-param-A-C2 = 物体 2 的热容
universality-param-A-R2 = 热阻（物体 2 至物体 1）
universality-param-B = 系统 B
universality-param-B-mass-spring = 质量–弹簧–阻尼器
universality-param-B-rlc = RLC 串联电路
universality-param-B-u-tube = U 形管压力计
universality-param-B-servo = 直流电机位置伺服（PD 控制）
universality-param-B-storey = 受地面运动作用的建筑楼层
universality-param-B-thermal = 双容热系统
universality-param-B-m = 质量
universality-param-B-c = 阻尼系数
universality-param-B-k = 弹簧刚度
universality-param-B-L = 电感
universality-param-B-R = 电阻
universality-param-B-C = 电容
universality-param-B-len = 液柱长度
universality-param-B-bore = 管内径
universality-param-B-rho = 液体密度
universality-param-B-mu = 动力黏度
universality-param-B-J = 电机与负载的转动惯量
universality-param-B-Kt = 电机转矩常数
universality-param-B-Ra = 电枢电阻
universality-param-B-Kp = 比例增益
universality-param-B-Kd = 微分增益
universality-param-B-mf = 楼板质量
universality-param-B-h = 层高
universality-param-B-EI = 4 根柱中每根的抗弯刚度
universality-param-B-cf = 楼层阻尼系数
universality-param-B-C1 = 物体 1 的热容
universality-param-B-R1 = 热阻（物体 1 至环境）
universality-param-B-C2 = 物体 2 的热容
universality-param-B-R2 = 热阻（物体 2 至物体 1）
universality-param-match = 匹配：调节 B，使其表现与 A 相同（ωₙ 和 ζ 相同）
universality-readout-a-A = A 的惯性系数 a
universality-readout-b-A = A 的阻尼系数 b
universality-readout-c-A = A 的刚度系数 c
universality-readout-wn-A = A 的固有频率 ωₙ
universality-readout-zeta-A = A 的阻尼比 ζ
universality-readout-regime-A = A 的阻尼状态
universality-readout-a-B = B 的惯性系数 a
universality-readout-b-B = B 的阻尼系数 b
universality-readout-c-B = B 的刚度系数 c
universality-readout-wn-B = B 的固有频率 ωₙ
universality-readout-zeta-B = B 的阻尼比 ζ
universality-readout-regime-B = B 的阻尼状态
universality-readout-wn-ratio = 时间尺度比 ωₙ(B)/ωₙ(A)
universality-readout-match = 匹配
universality-plot-normalised = 归一化响应 y/y₀ 随 ωₙt 的变化
universality-plot-realtime = 实际时间下的响应
universality-preset-1 = 质量–弹簧与 RLC 电路，已匹配
universality-preset-2 = U 形管压力计与质量–弹簧，已匹配
universality-preset-3 = 按伺服系统调节的建筑楼层
universality-preset-4 = 温度计（双容）与质量–弹簧，已匹配
universality-preset-5 = 热系统无法匹配振荡器
universality-table-caption = 一个方程，多种系统：y、a、b 和 c 分别是什么
universality-table-column-1 = 系统
universality-table-column-2 = 坐标 y
universality-table-column-3 = a
universality-table-column-4 = b
universality-table-column-5 = c
universality-table-column-6 = ωₙ
universality-table-column-7 = ζ
universality-table-mass-spring-1 = 质量–弹簧–阻尼器
universality-table-mass-spring-2 = 位移 x [m]
universality-table-mass-spring-3 = 质量 m [kg]
universality-table-mass-spring-4 = 阻尼系数 c [N·s/m]
universality-table-mass-spring-5 = 弹簧刚度 k [N/m]
universality-table-mass-spring-6 = √(k/m)
universality-table-mass-spring-7 = c/(2√(km))
universality-table-rlc-1 = RLC 串联电路
universality-table-rlc-2 = 电荷 q [C]
universality-table-rlc-3 = 电感 L [H]
universality-table-rlc-4 = 电阻 R [Ω]
universality-table-rlc-5 = 1/C [1/F]
universality-table-rlc-6 = 1/√(LC)
universality-table-rlc-7 = (R/2)·√(C/L)
universality-table-u-tube-1 = U 形管压力计
universality-table-u-tube-2 = 液面变化 h [m]
universality-table-u-tube-3 = ρAL [kg]
universality-table-u-tube-4 = 8πμL [N·s/m]
universality-table-u-tube-5 = 2ρgA [N/m]
universality-table-u-tube-6 = √(2g/L)
universality-table-u-tube-7 = 16μ/(ρd²ωₙ)
universality-table-servo-1 = 直流电机位置伺服（PD 控制）
universality-table-servo-2 = 角度误差 θ [rad]
universality-table-servo-3 = J [kg·m²]
universality-table-servo-4 = K_t(K_t + K_d)/R_a [N·m·s/rad]
universality-table-servo-5 = K_t·K_p/R_a [N·m/rad]
universality-table-servo-6 = √(K_t·K_p/(R_a·J))
universality-table-servo-7 = ≥ K_t²/(2ωₙR_a·J)，仅由反电动势产生
universality-table-storey-1 = 受地面运动作用的建筑楼层
universality-table-storey-2 = 层间位移 u [m]
universality-table-storey-3 = 楼板质量 m [kg]
universality-table-storey-4 = 阻尼系数 c [N·s/m]
universality-table-storey-5 = 12·4·EI/h³ [N/m]
universality-table-storey-6 = √(48EI/(m·h³))
universality-table-storey-7 = c/(2√(km))
universality-table-thermal-1 = 双容热系统
universality-table-thermal-2 = 温度超出量 T₂ [K]
universality-table-thermal-3 = R₁C₁R₂C₂ [s²]
universality-table-thermal-4 = R₁C₁ + R₂C₂ + R₁C₂ [s]
universality-table-thermal-5 = 1
universality-table-thermal-6 = 1/√(τ₁τ₂)
universality-table-thermal-7 = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1

### regimes

regimes-envelope = 包络线 ±A·e^(−ζωₙt)
regimes-series-response = x(t)，{ $regime }
regimes-describe-settles = { $regime }：{ $swings ->
        [0] 稳定前不越过平衡位置
        [1] 稳定前越过平衡位置一次
       *[other] 稳定前越过平衡位置 { $swings } 次
    }，{ $time } 后保持在距静止位置 5 % 以内，最大回弹 { $rebound }。
regimes-describe-unsettled = { $regime }：{ $swings ->
        [0] 稳定前不越过平衡位置
        [1] 稳定前越过平衡位置一次
       *[other] 稳定前越过平衡位置 { $swings } 次
    }，始终不稳定，最大回弹 { $rebound }。
regimes-describe-undamped = 无阻尼：以振幅 { $amplitude }、频率 { $frequency } 持续振荡。
regimes-describe-growing = 负阻尼：响应无限增长，每经过 { $time } 增大为原来的 e 倍。
regimes-describe-at-rest = { $regime }：从平衡位置静止开始。
regimes-poles = 极点位于 { $re1 } { $sign1 } { $im1 }i 和 { $re2 } { $sign2 } { $im2 }i 1/s，在{ $side ->
        [right] 右半平面（不稳定）
       *[left] 左半平面（稳定）
    }。
regimes-schematic = t = { $time } 时弹簧–阻尼器上的质量：偏离静止位置 { $displacement }。
regimes-title = 阻尼状态
regimes-summary = 从 x(0) = x₀、x′(0) = v₀ 开始的自由响应。阻尼比 ζ 决定阻尼状态：ζ = 0 为无阻尼，0 < ζ < 1 为欠阻尼，ζ = 1 为临界阻尼，ζ > 1 为过阻尼，ζ < 0 为负阻尼（响应增长）。极点 s = −ζωₙ ± ωₙ√(ζ² − 1) 沿半径为 ωₙ 的圆移动，在 ζ = 1 时到达实轴，在 ζ = 0 时穿过虚轴。
regimes-param-wn = 固有频率
regimes-param-zeta = 阻尼比
regimes-param-x0 = 初始位移
regimes-param-v0 = 初始速度
regimes-readout-regime = 阻尼状态
regimes-readout-wn = 固有频率 ωₙ
regimes-readout-zeta = 阻尼比 ζ
regimes-readout-wd = 阻尼频率 ω_d
regimes-readout-pole-re = 极点实部
regimes-readout-pole-im = 极点虚部
regimes-plot-response = 自由响应 x(t)
regimes-plot-poles = s 平面上的极点
regimes-preset-1 = 无阻尼 ζ = 0
regimes-preset-2 = 欠阻尼 ζ = 0.2
regimes-preset-3 = 临界阻尼 ζ = 1
regimes-preset-4 = 过阻尼 ζ = 2
regimes-preset-5 = 负阻尼 ζ = −0.1
regimes-table-caption = 各种阻尼状态
regimes-table-column-1 = 阻尼状态
regimes-table-column-2 = 条件
regimes-table-column-3 = 根 s₁、s₂
regimes-table-column-4 = 行为
regimes-table-column-5 = 工程实例
regimes-table-undamped-1 = 无阻尼
regimes-table-undamped-2 = ζ = 0
regimes-table-undamped-3 = ±iωₙ，位于虚轴上
regimes-table-undamped-4 = 以 ωₙ 持续振荡
regimes-table-undamped-5 = 理想单摆、LC 振荡回路
regimes-table-underdamped-1 = 欠阻尼
regimes-table-underdamped-2 = 0 < ζ < 1
regimes-table-underdamped-3 = −ζωₙ ± iω_d，共轭复根
regimes-table-underdamped-4 = 以 ω_d 衰减振荡
regimes-table-underdamped-5 = 汽车悬架（ζ ≈ 0.2–0.7）、吉他弦
regimes-table-critically-damped-1 = 临界阻尼
regimes-table-critically-damped-2 = ζ = 1
regimes-table-critically-damped-3 = −ωₙ，二重实根
regimes-table-critically-damped-4 = 不振荡的最快回复
regimes-table-critically-damped-5 = 闭门器、模拟仪表指针
regimes-table-overdamped-1 = 过阻尼
regimes-table-overdamped-2 = ζ > 1
regimes-table-overdamped-3 = 两个负实根
regimes-table-overdamped-4 = 缓慢回复，无振荡
regimes-table-overdamped-5 = 重型液压阻尼器、温度计
regimes-table-negatively-damped-1 = 负阻尼
regimes-table-negatively-damped-2 = ζ < 0
regimes-table-negatively-damped-3 = 右半平面
regimes-table-negatively-damped-4 = 振荡增长
regimes-table-negatively-damped-5 = 颤振（塔科马海峡大桥）、刹车尖叫
### quarter-car

quarter-car-legend-comfort = 舒适 { $low }、{ $high }
quarter-car-legend-performance = 运动 { $low }、{ $high }
quarter-car-legend-critical = 临界 { $zeta }（×）
quarter-car-legend-overdamped = 过阻尼 { $zeta }（●）
quarter-car-group = { $group ->
        [comfort] 舒适
        [performance] 运动
        [critical] 临界
       *[overdamped] 过阻尼
    }
quarter-car-crossings = { $count ->
        [0] 不穿越平衡位置
        [1] 稳定前穿越平衡位置一次
       *[other] 稳定前穿越平衡位置 { $count } 次
    }
quarter-car-crossings-inside-band = 未穿越平衡位置即已稳定（其回弹留在误差带内）
quarter-car-settles-after = { $time } 后保持在静止位置附近 x₀ 的 ±{ $band } 以内
quarter-car-does-not-settle = 不能稳定
quarter-car-rebound = 最大回弹 { $rebound }（t = { $time }）
quarter-car-no-rebound = 无回弹
quarter-car-describe-design = 当前设计（ζ = { $zeta }，{ $regime }）：{ $crossings }，{ $settling }，{ $rebound }。
quarter-car-describe-undamped = 当前设计（ζ = 0，无阻尼）：以 { $frequency } 在 ±{ $amplitude } 之间永远振荡。
quarter-car-describe-unsettled = 当前设计（{ $regime }）：不能稳定。
quarter-car-list-separator = {"；"}
quarter-car-describe-response = { $design }本车上的各预设设定进入 x₀ 的 ±{ $band } 误差带：{ $family }。
quarter-car-member-settles = { $group } ζ = { $zeta } 用时 { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } 不能稳定
quarter-car-two-sentences = { $first }{ $second }
quarter-car-settling-fastest = 本车自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化：ζ = { $zeta } 时最快（{ $time }），恰在一次跳变之后；每当一次回弹落入误差带内，调节时间就向下跳变。
quarter-car-settling-curve = 自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化。
quarter-car-settling-design = 当前设计 ζ = { $zeta }，调节时间为 { $time }。
quarter-car-settling-design-never = 当前设计 ζ = { $zeta }，永远不能稳定。
quarter-car-sensitivity-range = 簧上质量在 { $low } 到 { $high } 之间（±{ $variation }）且阻尼器和弹簧不变时，ζ 从 { $min } 变化到 { $max }（标称值 { $nominal }）；线性估计为 { $linear_min } 到 { $linear_max }。
quarter-car-sensitivity-undefined = 此设计的阻尼比范围无定义。
quarter-car-sensitivity-inside = 调节最快的 ζ = { $zeta } 位于此范围内：使 ζ 低于该值的载荷会使调节明显变慢。
quarter-car-sensitivity-outside = 调节最快的 ζ = { $zeta } 位于此范围之外。
quarter-car-schematic = 四分之一车辆，t = { $time }：车身{ $side ->
        [above] 高于
       *[below] 低于
    }静止位置 { $displacement }，路面固定。
quarter-car-settling-title = 进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化
quarter-car-axis-zeta = 阻尼比 ζ
quarter-car-axis-zeta-fastest = 阻尼比 ζ（虚线：最快 ζ = { $zeta }）
quarter-car-axis-settling-time = 调节时间 t_s
quarter-car-axis-sprung-mass = 簧上质量 m
quarter-car-fastest = 最快 ζ = { $zeta }
quarter-car-this-design = 当前设计
quarter-car-nominal = 标称值
quarter-car-road = 路面
quarter-car-band-label = x₀ 的 ±{ $band }
quarter-car-series-design = 当前设计，ζ { $zeta }
quarter-car-title = 四分之一车辆悬架
quarter-car-summary = 汽车的一个角：车身（簧上质量 m）支承在弹簧 k 和阻尼器 c 上，下方路面固定；车身被推离 x₀ 后从静止释放（x′(0) = 0）。c 和 ζ 是同一个阻尼器的两种表示，c = 2ζ√(km)：移动其中一个，另一个随之改变；改变 m 或 k 时阻尼器不变，因此 ζ 随之改变。细曲线是本车上的教科书式设定：舒适型（ζ ≈ 0.3–0.4）有回弹，运动型（ζ ≈ 0.65–0.7）稳定最快，临界（ζ = 1）和过阻尼设定无回弹地返回，但更慢。当 ζ 经过使某次回弹落入误差带内的数值时，调节时间发生跳变：最快的 ζ 恰好位于这样一次跳变之后，因此更重的载荷可能使调校良好的车越过这一边缘（见质量条带图）。调节以这一自由响应衡量：调节时间是 |x| 最后一次等于 误差带·|x₀| 的时刻，此后车身保持在静止位置的 ±误差带·|x₀| 以内（而不是阶跃响应终值附近的误差带）。
quarter-car-param-m = 簧上质量
quarter-car-param-k = 弹簧刚度
quarter-car-param-c = 阻尼器阻尼系数
quarter-car-param-zeta = 阻尼比
quarter-car-param-x0 = 初始位移
quarter-car-param-band = 静止位置附近的调节误差带（相对于 x₀）
quarter-car-param-dm = 簧上质量变化
quarter-car-readout-regime = 阻尼状态
quarter-car-readout-wn = 固有频率 ωₙ
quarter-car-readout-fn = 固有频率 fₙ
quarter-car-readout-zeta = 阻尼比 ζ
quarter-car-readout-c = 当前阻尼系数 c
quarter-car-readout-c-crit = 临界阻尼 2√(km)
quarter-car-readout-wd = 阻尼频率 ω_d
quarter-car-readout-settling-time = 进入 ±误差带·|x₀| 的调节时间 t_s（自由响应）
quarter-car-readout-overshoot = 最大回弹（相对于 x₀）
quarter-car-readout-peak-time = 最大回弹时刻
quarter-car-readout-zeta-argmin = 调节最快的 ζ（自由响应，相同误差带）
quarter-car-readout-settling-min = 其调节时间
quarter-car-readout-zeta-lo = 质量 +dm % 时的 ζ
quarter-car-readout-zeta-hi = 质量 −dm % 时的 ζ
quarter-car-plot-response = 车身位移 x(t)
quarter-car-plot-settling = 自由响应调节时间随 ζ 的变化
quarter-car-plot-sensitivity = 簧上质量变化时的 ζ
quarter-car-preset-1 = 舒适 ζ = 0.3
quarter-car-preset-2 = 舒适 ζ = 0.4
quarter-car-preset-3 = 运动 ζ = 0.65
quarter-car-preset-4 = 运动 ζ = 0.7
quarter-car-preset-5 = 临界 ζ = 1
quarter-car-preset-6 = 过阻尼 ζ = 2

### quarter-car-2dof

quarter-car-2dof-describe-motion = 经过{ $road ->
        [bump] 一个凸起
        [step] 一个台阶
        [sine] 正弦路面
       *[random] 随机路面
    }（最大路面高度 { $road_peak }），车身最大位移 { $body }（t = { $body_time }），车轮最大位移 { $wheel }（t = { $wheel_time }）。
quarter-car-2dof-describe-acceleration = 车身加速度峰值为 { $peak }（{ $peak_g } g）；在从静止开始的整个过程（0 到 { $window }）中，其均方根值为 { $rms }。
quarter-car-2dof-describe-tyre-lift-off = 轮胎变形（车轮高于路面，正值 = 轮胎卸载）范围为 { $low } 到 { $high }，均方根值 { $rms }；在 { $time } 首次达到静态变形 { $limit }，此时轮胎力降为零，车轮离开路面：离地 { $lift_offs } 次；离地时间 { $airborne }。
quarter-car-2dof-describe-tyre-contact = 轮胎变形（车轮高于路面，正值 = 轮胎卸载）范围为 { $low } 到 { $high }，均方根值 { $rms }；始终低于静态变形 { $limit }，因此轮胎保持接地。
quarter-car-2dof-describe-frf = 单位路面高度的频率响应，采用对数坐标。车身跟随缓慢的路面起伏（比值 1），在车身跳动频率 { $body_frequency } 附近达到峰值 { $body_peak }，更高频率处被隔离：20 Hz 时为 { $at_20 }。轮胎变形在车轮跳动频率 { $tyre_frequency } 附近达到峰值 { $tyre_peak }。
quarter-car-2dof-schematic = 四分之一车辆，t = { $time }：车身 { $body }，车轮 { $wheel }，路面 { $road }（按同一比例绘制）。
quarter-car-2dof-schematic-title = 示意图
quarter-car-2dof-axis-height = 相对平衡位置的高度
quarter-car-2dof-axis-acceleration = 加速度 z_s″
quarter-car-2dof-axis-tyre-deflection = 轮胎变形 z_u − u
quarter-car-2dof-axis-frequency = 频率 f
quarter-car-2dof-axis-magnitude = 单位路面高度的幅值
quarter-car-2dof-series-road = 路面 u
quarter-car-2dof-series-wheel = 车轮 z_u
quarter-car-2dof-series-body = 车身 z_s
quarter-car-2dof-series-body-acceleration = 车身加速度
quarter-car-2dof-series-rms = ± 均方根
quarter-car-2dof-series-lift-off = 离地界限（静态变形）
quarter-car-2dof-series-off-road = 车轮离地
quarter-car-2dof-series-body-gain = 车身/路面
quarter-car-2dof-series-tyre-gain = 轮胎变形/路面
quarter-car-2dof-marker-road = 路面
quarter-car-2dof-title = 含车身与车轮的四分之一车辆
quarter-car-2dof-summary = 两个质量，两个模态。车身（簧上质量 m_s）支承在悬架弹簧 k_s 和阻尼器 c_s 上；车轮（簧下质量 m_u）支承在轮胎弹簧 k_t 上，轮胎跟随路面 u(t)。车身跳动约在 1–1.5 Hz，是车身在较软悬架上的运动；车轮跳动约在 10–15 Hz，是较轻的车轮在刚硬的轮胎与悬架之间弹跳。频率响应同时显示两者：车身跟随缓慢的路面起伏，越过快速的起伏，在车身跳动附近振动最大；决定抓地力的轮胎变形在车轮跳动处达到峰值。轮胎只能推不能拉：当车轮升高超过其静态变形时，轮胎力为零，车轮离开路面，直到再次落地。舒适性以车身加速度均方根（RMS）衡量，抓地性以轮胎变形均方根衡量，两者都在从静止开始的整个过程 0 … T 内计算。在路面采样点之间响应是精确的，采样点足够密，可以跟上每个凸起和每次车轮跳动。位移从静平衡位置算起，向上为正；随机路面由 64 个正弦分量叠加而成，在 0.5–20 Hz 内符合 ISO 8608 谱。在随机路面上，页面还根据车辆的李雅普诺夫方程给出完整 ISO 8608 路面上的稳态车身加速度均方根，包括未加权值和按 ISO 2631-1 的 W_k 加权的值（a_w，舒适性指标）。
quarter-car-2dof-param-ms = 车身（簧上）质量
quarter-car-2dof-param-mu = 车轮（簧下）质量
quarter-car-2dof-param-ks = 悬架刚度
quarter-car-2dof-param-kt = 轮胎刚度
quarter-car-2dof-param-cs = 悬架阻尼
quarter-car-2dof-param-road = 路面输入
quarter-car-2dof-param-road-bump = 单个凸起（1 − cos）
quarter-car-2dof-param-road-step = 台阶（路缘）
quarter-car-2dof-param-road-sine = 正弦
quarter-car-2dof-param-road-random = 随机路面（ISO 8608）
quarter-car-2dof-param-h = 凸起或台阶高度、正弦幅值
quarter-car-2dof-param-L = 凸起长度
quarter-car-2dof-param-V = 车速
quarter-car-2dof-param-f-road = 正弦路面频率
quarter-car-2dof-param-class = 随机路面等级
quarter-car-2dof-param-class-A = A（很好）
quarter-car-2dof-param-class-B = B（好）
quarter-car-2dof-param-class-C = C（一般）
quarter-car-2dof-param-class-D = D（差）
quarter-car-2dof-param-class-E = E（很差）
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = 随机路面种子
quarter-car-2dof-readout-f-body = 车身跳动频率 [Hz]
quarter-car-2dof-readout-f-wheel = 车轮跳动频率 [Hz]
quarter-car-2dof-readout-window = 均方根统计区间：从静止开始的整个过程，0 … T
quarter-car-2dof-readout-rms-body-accel = 0 … T 内车身加速度均方根（舒适性）
quarter-car-2dof-readout-rms-tyre-deflection = 0 … T 内轮胎变形 z_u − u 的均方根（抓地性）
quarter-car-2dof-readout-max-travel = 最大悬架行程 |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = 轮胎静态变形（超过即车轮离地）
quarter-car-2dof-readout-lift-off = 首次离地：轮胎力降为零
quarter-car-2dof-readout-airborne-time = 车轮离地时间
quarter-car-2dof-readout-rms-road = 路面高度均方根（随机路面）
quarter-car-2dof-readout-stationary-accel = 稳态车身加速度均方根，完整 ISO 8608 路面（随机路面）
quarter-car-2dof-readout-stationary-weighted-accel = 稳态 a_w：按 ISO 2631-1 W_k 加权的车身加速度均方根（随机路面）
quarter-car-2dof-readout-body-gain = 正弦频率下车身与路面的幅值比
quarter-car-2dof-readout-tyre-gain = 正弦频率下轮胎变形与路面幅值之比
quarter-car-2dof-plot-motion = 车身、车轮与路面
quarter-car-2dof-plot-accel = 车身加速度
quarter-car-2dof-plot-frf = 单位路面高度的频率响应
quarter-car-2dof-plot-tyre = 轮胎变形
quarter-car-2dof-preset-1 = 减速带 5 cm，10 m/s
quarter-car-2dof-preset-2 = 路缘台阶 5 cm
quarter-car-2dof-preset-3 = 车身跳动频率的路面波
quarter-car-2dof-preset-4 = 车轮跳动频率的路面波
quarter-car-2dof-preset-5 = 随机路面，C 级，20 m/s
quarter-car-2dof-preset-6 = 差路面上的软阻尼器


### paper

paper-unavailable = 此图对应的演示不可用
paper-figure = 图 { $number }
paper-section = 第 { $number } 节
paper-section-figure = 第 { $section } 节，图 { $figure }
paper-near-agrees = 演示计算得 { $computed }，在舍入范围内与论文的 { $claimed } 相符（容差 ±{ $tolerance }）。
paper-near-differs = 演示计算得 { $computed }，与论文的 { $claimed } 不符（容差 ±{ $tolerance }）。
paper-below-agrees = 演示计算得 { $computed }，低于论文给出的上限 { $bound }。
paper-below-differs = 演示计算得 { $computed }，高于论文给出的上限 { $bound }。
paper-range = { $low } 至 { $high }
paper-range-agrees = 演示计算得 { $low } 至 { $high }，与论文所述一致。
paper-range-differs = 演示计算得 { $low } 至 { $high }，与论文给出的范围不符。
paper-peak = 通过搜索得到的 |H(r)| 最大值位于 r = { $found }，而公式给出的是 { $formula }。
paper-slope = 在论文的步长 h = { $step } 及其五次减半（直至 { $smallest }）上，拟合斜率为 { $slope }。
paper-reason-context = { $verdict }{ $context }
paper-exhibit-fig1a = 四分之一车辆模型（m = 300 kg，k = 24 kN/m，x₀ = 60 mm）在舒适、性能、临界阻尼和过阻尼设置下的自由响应。
paper-exhibit-fig1b = 调节时间随阻尼比的变化及其最小值。
paper-exhibit-fig2a = 串联 RLC 回路（L = 0.5 H，C = 20 mF，V₀ = 12 V）中电阻跨越各阻尼状态时的电流。
paper-exhibit-fig2b = 同一回路的电容电压。
paper-exhibit-fig3a = 一组阻尼比下频率响应的幅值。
paper-exhibit-fig3b = 频率响应的相位。
paper-exhibit-fig4a = 轻阻尼振子（ζ = 0.05，ωₙ = 2 rad/s）在 h = 0.3 s 时欧拉法和 RK4 与精确响应的对比。
paper-exhibit-fig4b = 双对数坐标下最大误差随步长的变化及其斜率。
paper-exhibit-fig5 = 一个方程，多种机器：满足同一方程 a·y'' + b·y' + c·y = f(t) 的机械、电气及其他系统。
paper-exhibit-table1 = 机电类比：质量 ↔ 电感，阻尼器 ↔ 电阻，弹簧 ↔ 1/电容。
paper-exhibit-table2 = 各种阻尼状态：条件、根、行为与实例。
paper-exhibit-table3 = 积分方法比较：同一步长下的误差、阶数与稳定性。
paper-claim-fig1-zeta-optimum = 阻尼比约为 0.7 时调节时间最短（5 % 误差带）。
paper-claim-sec3-natural-frequency = 四分之一车辆模型的固有频率约为 8.9 rad/s（约 1.4 Hz）。
paper-claim-sec4-critical-resistance = 当 R = 2√(L/C) = 10 Ω 时回路处于临界阻尼。
paper-claim-fig3-q-factor = ζ = 0.05 时 Q = 10。
paper-claim-fig3-q-factor-light = ζ = 0.01 时 Q = 50。
paper-claim-sec5-peak-frequency = 响应在 ω = ωₙ√(1 − 2ζ²) 处达到峰值，略低于 ωₙ（在 ζ = 0.1 时核对）。
paper-claim-fig4-euler-error = h = 0.3 s 时欧拉法的最大误差约为 0.08。
paper-claim-fig4-rk4-error = h = 0.3 s 时 RK4 的最大误差小于 0.001。
paper-claim-fig4-euler-slope = 在双对数图上，欧拉法的误差以斜率 ≈ 1 下降。
paper-claim-sec7-mass-tolerance = 簧上质量 ±10 % 的不确定性使 ζ = 1.0 变为 0.91 至 1.10 之间的值。
paper-claim-fig1-zeta-optimum-context = 若取 2 % 误差带，调节最快的 ζ 则为 { $value }。
paper-claim-sec3-natural-frequency-context = 以赫兹计：fₙ = { $value }。
paper-claim-fig4-euler-error-context = 欧拉法在此步长下不稳定：每步 |1 + hλ| = { $value }，因此其误差无界增长。
paper-claim-fig4-rk4-error-context = RK4 在此步长下稳定（每步 |R(hλ)| = { $value }），但在整个时间窗口内其误差仍超过该上限。
paper-claim-fig4-euler-slope-context = 在误差处于渐近区的小步长上拟合得到的阶数为 { $value }。
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) 与 1/√m 成正比，因此质量变化 ±10 % 只使其改变约 ±5 %（质量增加 10 % 时 ωₙ 降至 { $value }）。
paper-title = 论文逐项核对
paper-summary = Zeta Lab 源自一篇关于机械与电气系统中二阶微分方程的论文（Ihenacho、Samuel、Okechukwu 等，Science Publishing Group，2026）。这里列出论文中的每一幅图和每一张表，均由复现它的演示实时绘制；论文给出的每一个数值都经过核对：每条论断都显示论文的数值、本应用计算的数值和结论。点击链接即可在完全相同的状态下打开该演示。
paper-readout-claims = 已核对的论断
paper-readout-confirmed = 已证实的论断
paper-readout-differs = 有出入的论断
paper-plot-fig1a = 图 1(a)
paper-plot-fig1b = 图 1(b)
paper-plot-fig2a = 图 2(a)
paper-plot-fig2b = 图 2(b)
paper-plot-fig3a = 图 3(a)
paper-plot-fig3b = 图 3(b)
paper-plot-fig4a = 图 4(a)
paper-plot-fig4b = 图 4(b)
paper-plot-fig5 = 图 5
paper-plot-table1 = 表 1
paper-plot-table2 = 表 2
paper-plot-table3 = 表 3

## 示意图

schematic-title = 示意图
schematic-circuit = 电路
### rlc

rlc-axis-current = 电流 i
rlc-axis-voltage = 电容电压 v_C
rlc-envelope = 包络线
rlc-series-critical = 临界 R = { $resistance }
rlc-schematic = t = { $time } 时的 RLC 串联回路：电流 { $current }，电容电压 { $voltage }。
rlc-describe-current = { $regime ->
        [undamped] R = { $resistance }，无阻尼（无损 LC 回路）：电流以 ω₀ = { $frequency } 持续振荡，在 ±{ $bound } 之间变化（每半个周期，全部能量转入电感后又返回）。
        [underdamped] R = { $resistance }，低于临界电阻 { $critical }，欠阻尼：电流以 ω_d = { $ringing } 振荡（Q = { $q }），按 e^(−αt) 衰减，α = { $alpha }；电流始终不超过 { $bound }。
        [critical] R = { $resistance }，等于临界电阻，临界阻尼：只有一个电流脉冲（为负，电容正在放电），回到零而不反向；电流始终不超过 { $bound }。
       *[overdamped] R = { $resistance }，高于临界电阻 { $critical }，过阻尼：一个缓慢的电流脉冲（为负，电容正在放电），不反向，慢时间常数为 { $time }。
    }
rlc-describe-voltage = { $regime ->
        [undamped] R = { $resistance }，无阻尼（无损 LC 回路）：电容电压以 ω₀ = { $frequency } 在 +{ $voltage } 与 −{ $voltage } 之间持续振荡。
        [underdamped] R = { $resistance }，低于临界电阻 { $critical }，欠阻尼：电容电压{ $reversal ->
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
        [critical] R = { $resistance }，等于临界电阻，临界阻尼：电容以最快速度放电且不反向；{ $settles ->
            [yes] 电压在 { $time } 后保持在 V₀ 的 5 % 以内
           *[no] 电压始终不稳定
        }。
       *[overdamped] R = { $resistance }，高于临界电阻 { $critical }，过阻尼：电容缓慢放电且不反向；{ $settles ->
            [yes] 电压在 { $time } 后保持在 V₀ 的 5 % 以内
           *[no] 电压始终不稳定
        }。
    }
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
quarter-car-2dof-readout-f-body = 车身跳动频率
quarter-car-2dof-readout-f-wheel = 车轮跳动频率
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
paper-pending-plot = 完整应用加载后绘制
paper-pending-mark = 加载中…
paper-pending-value = …
paper-pending = 完整应用加载后即刻核对。
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

### resonance

resonance-axis-ratio = 频率比 r = ω/ωₙ
resonance-axis-amplification = 放大系数 |H| = X/(F₀/k)
resonance-axis-magnitude-db = 幅值 20·log₁₀|H|
resonance-axis-phase = 相位 ∠H（x 滞后于 F）
resonance-plot-magnitude-db = 放大系数 |H(r)|（dB）
resonance-family = 曲线族 ζ = { $from } … { $to }
resonance-current = 当前 ζ = { $zeta }
resonance-drive = 驱动 r = { $ratio }
resonance-peak = 峰值
resonance-quadrature = r = 1 处 −90°
resonance-legend-width = 半功率宽度 r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2，直到 r = { $upper }
resonance-legend-cutoff = −3 dB 截止 r = { $upper }
resonance-band-width = 半功率点（|H| = |H|max/√2）位于 r = { $lower } 和 { $upper }：峰宽 r₂ − r₁ = { $width }
resonance-band-broad = 从 r = 0 到 r = { $upper }，|H| 始终高于 |H|max/√2：该峰没有下半功率点，因此其半功率宽度无定义
resonance-band-cutoff = |H| 在截止频率比 r = { $upper } 处降至静态值的 1/√2（−3 dB）；没有峰，也就没有半功率宽度
resonance-peak-at = 共振峰 { $gain }，位于 r = { $ratio }
resonance-no-peak = 没有共振峰（ζ ≥ 1/√2）：|H| 从 r = 0 处的 1 单调下降
resonance-describe-magnitude = { $view ->
        [db] ζ = { $zeta } 时的幅值（dB）：{ $peak }；{ $band }。在驱动频率比 r = { $drive } 处，放大系数为 { $gain }。
       *[linear] ζ = { $zeta } 时的幅值：{ $peak }；{ $band }。在驱动频率比 r = { $drive } 处，放大系数为 { $gain }。
    }
resonance-describe-phase = ζ = { $zeta } 时位移相对于力的相位滞后：低频时为 0°，对任何阻尼比在 r = 1 处均为 −90°，共振以上趋于 −180°；ζ 越小，转变越陡。在驱动频率比 r = { $drive } 处，滞后为 { $degrees }（{ $radians } rad）。
resonance-envelope = 包络线 ±E(t)
resonance-steady-amplitude = 稳态振幅 ±X
resonance-describe-time-growing = 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：没有稳态；振幅不断增大，达到 { $largest }。
resonance-describe-time = { $case ->
        [beats] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：自由运动与受迫运动形成拍，拍周期为 { $period }（衰减时间常数 { $tau }），趋向稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
        [build-up] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：在共振处振幅以时间常数 1/(ζωₙ) = { $tau } 逐渐增大，趋向稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
       *[transient] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：经过瞬态过程（时间常数 { $tau }）后稳定在稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
    }
resonance-fixed-base = 固定基座
resonance-schematic = 固定基座上由弹簧和阻尼器支承的质量块，受力 F(t) = { $force } 推动（质量块上方的箭头），t = { $time }：偏离静止位置 { $displacement }。
resonance-beats-visible = 可见
resonance-beats-no-free-oscillation = 无（没有自由振荡，ζ ≥ 1）
resonance-beats-no-drive = 无（恒定力）
resonance-beats-same-frequency = 无（以 ω_d 驱动）
resonance-beats-too-fast = 无（与振荡一样快）
resonance-beats-dies-out = 无（自由运动先衰减消失）
resonance-title = 受迫共振
resonance-summary = 一个 1 kg 的质量块连接弹簧（k = ωₙ²·m）和阻尼器（c = 2ζωₙ·m），从静止开始，自 t = 0 起受力 F(t) = F₀·cos(ωt) 驱动。稳态时它以驱动频率运动，振幅为 |H(r)|·F₀/k，滞后于力的相角等于 H 的相位，其中 r = ω/ωₙ。轻阻尼在 r = 1 附近产生又高又窄的峰（高度 ≈ Q = 1/(2ζ)）。其半功率宽度，即 |H| = |H|max/√2 的两个频率比之间的 r₂ − r₁，在轻阻尼时 ≈ 2ζ；ζ ≈ 0.383 以上，下半功率点到达 r = 0，宽度无定义；ζ = 1/√2 以上则完全没有峰。恰好在共振处驱动时，振幅在几个时间常数 1/(ζωₙ) 内逐渐增大，不出现拍；在共振附近驱动时，自由运动与受迫运动相互形成拍，直到自由部分衰减消失。
resonance-param-zeta = 阻尼比
resonance-param-r = 激励频率比 ω/ωₙ
resonance-param-wn = 固有频率
resonance-param-F0 = 力幅值
resonance-param-view = 幅值显示方式
resonance-param-view-linear = 线性 |H|
resonance-param-view-db = 分贝 20·log₁₀|H|
resonance-readout-peak-gain = 共振峰 |H|max
resonance-readout-peak-ratio = 峰值位置 r = ω/ωₙ
resonance-readout-Q = 品质因数 Q = 1/(2ζ)
resonance-readout-peak-width = |H| 峰的半功率宽度 r₂ − r₁（ζ < 0.383）
resonance-readout-gain-at-r = 驱动处的增益 |H(r)|
resonance-readout-phase-at-r = 驱动处的相位 ∠H(r)
resonance-readout-amplitude = 稳态振幅 X = |H|·F₀/k
resonance-readout-beat-period = 拍周期 2π/|ω − ω_d|（出现拍时）
resonance-readout-beats = x(t) 中的拍
resonance-plot-magnitude = 放大系数 |H(r)|
resonance-plot-phase = 相位 ∠H(r)
resonance-plot-time = 从静止开始的响应 x(t)
resonance-preset-1 = 共振处，ζ = 0.05
resonance-preset-2 = 共振附近的拍，r = 0.9
resonance-preset-3 = 无峰，ζ ≈ 1/√2
resonance-preset-4 = 准静态，r = 0.2
resonance-preset-5 = 隔振，r = 3

### flutter

flutter-no-oscillation = 无振荡
flutter-series-h-section = 1940 年 H 形截面（教学近似）
flutter-series-box = 流线型箱梁（薄平板，Theodorsen）
flutter-series-simplest = 最简模型等效的 A₂*
flutter-series-simplest-line = 最简模型 ζ_s − g·U
flutter-axis-reduced-velocity = 折减风速 U/(f·B) = 2π/K
flutter-axis-wind-speed = 风速 U
flutter-axis-effective-damping = 有效阻尼比 ζ_eff
flutter-axis-twist = 扭转角 θ
flutter-threshold = 阈值 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = 上极点
flutter-lower-pole = 下极点
flutter-amplitude = 振幅 ±a(t)
flutter-limit-cycle = 极限环 ±{ $amplitude }
flutter-describe-derivative = { $model ->
        [h] 1940 年 H 形截面的 A₂* 随折减风速的变化（教学近似，并非实测值）
        [box] 流线型箱梁（理想化为薄平板，取 Theodorsen 势流精确值）的 A₂* 随折减风速的变化
       *[simplest] 最简模型的 A₂* 随折减风速的变化（即其关于 U 的直线所相当的 A₂*）
    }：A₂* 超过 4Iζ_s/(ρB⁴) 时扭转增大。
flutter-describe-derivative-now = { $description }在 U = { $speed }（K = { $k }，U/(fB) = { $reduced_velocity }）时，A₂* = { $a2 }，{ $side ->
        [above] 高于
       *[below] 低于
    }阈值 { $threshold }。
flutter-describe-damping = { $model ->
        [h] 1940 年 H 形截面
        [box] 流线型箱梁
       *[simplest] 最简模型
    }的有效阻尼比，静风时从 ζ_s = { $zeta_s } 开始；{ $crossing ->
        [inside] 在临界风速 { $speed } 处过零
        [beyond] 只有在 { $speed } 才会过零，超出图中最大值 { $limit }
       *[never] 直到 100 m/s 都不过零：风只增加阻尼
    }。
flutter-describe-damping-now = { $description }在 U = { $speed } 时为 { $zeta }，{ $sign ->
        [positive] 为正（稳定）
        [negative] 为负（颤振）
       *[zero] 为零
    }。
flutter-describe-damping-still = { $description }在此风速下桥面不振荡。
flutter-describe-locus = 风速增大时的极点对：静风时为 { $re_calm } ± { $im_calm }i 1/s，在 { $limit } 时为 { $re_end } ± { $im_end }i 1/s，{ $crosses ->
        [yes] 在 U_crit 处穿过虚轴
       *[no] 始终不穿过虚轴
    }。
flutter-describe-locus-now = { $description }在 U = { $speed } 时，极点为 { $re } ± { $im }i 1/s，位于{ $side ->
        [right] 右半平面（不稳定）
       *[left] 左半平面（稳定）
    }。
flutter-oscillation = 振荡
flutter-oscillation-at = { $frequency } Hz 的振荡
flutter-describe-response = { $regime }：从初始扭转角 { $twist } 开始，{ $oscillation }{ $case ->
        [settling] 在图末（{ $window }）增大到 { $end }，接近 { $limit } 的极限环（{ $time } 后达到其 90%）
        [slow] 在图末（{ $window }）只增大到 { $end }；要达到 { $limit } 极限环的 90% 需要 { $time }
        [settled] 在图末（{ $window }）稳定在 { $limit } 的极限环上
        [grows] 在图末（{ $window }）增大到 { $end }
       *[dies] 在图末（{ $window }）衰减到 { $end }
    }。
flutter-describe-response-torn = { $description }如此大的扭转早已使任何桥面断裂；该界限只是一个教学假设。
flutter-schematic-title = 桥面截面
flutter-drawn-clipped = 绘图在 { $angle } 处截断
flutter-drawn-true-scale = 按真实比例绘制
flutter-drawn-larger = 放大 { $factor } 倍绘制
flutter-drawn-note = （{ $drawn }）
flutter-schematic = t = { $time } 时的桥面截面：扭转 { $twist }（{ $drawn }），风速 { $wind }，风从左侧吹来。
flutter-wind = 风速 U = { $speed }
flutter-title = 颤振：塔科马海峡大桥
flutter-summary = 稳定的风可以通过扭转桥面自身的运动向其输入能量。Scanlan 用风洞中测得的颤振导数描述风作用在扭转桥面上的力矩：A₂* 乘以扭转角速度（阻尼项），A₃* 乘以扭转角（刚度项），二者都是折减频率 K = Bω/U 的函数。桥面的阻尼比变为 ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I)：对于 1940 年塔科马桥面的钝体 H 形截面，A₂* 随风速增大而改变符号，一旦超过阈值 4Iζ_s/(ρB⁴)，任何微小扭转都会以桥面自身的扭转频率（约 0.2 Hz）增长——这是颤振，不是共振：稳定的风没有可以匹配的频率，运动自己产生激励。由于 K 依赖于频率，在每个风速下用迭代求频率。线性理论让扭转无限增长；这里假设风的阻尼项在扭转角 θ_s 时减半，从而把运动限制在一个大的极限环内，正如 1940 年 11 月 7 日那样：在约 42 mph 的风中，扭转在一小时内不断增大，直到桥面撕裂。特此说明：H 形截面的 A₂* 和 A₃* 是教学近似，即形状仿照已发表风洞结果（Scanlan 与 Tomko 1971；Billah 与 Scanlan 1991）的光滑曲线，并非从中读取的数值；I、ζ_s 和 θ_s 为假设值。流线型箱梁理想化为薄平板，其 A₂* 和 A₃* 在势流中是精确的（Theodorsen 1935）：它的 A₂* 始终为负，因此在此范围内从不发生颤振。保留最简模型 ζ_eff = ζ_s − g·U 以作比较。
flutter-param-U = 风速
flutter-param-model = 风致力矩模型
flutter-param-model-scanlan = 颤振导数（Scanlan）
flutter-param-model-linear = 最简模型：ζ_eff = ζ_s − g·U
flutter-param-section = 桥面截面
flutter-param-section-h = 1940 年 H 形截面（板梁）
flutter-param-section-box = 流线型箱梁
flutter-param-B = 桥面宽度
flutter-param-I = 单位长度质量惯性矩（1940 年的假设值）
flutter-param-f0 = 静风中的扭转频率
flutter-param-zeta-s = 结构阻尼比（1940 年的假设值）
flutter-param-theta0 = 初始扭转角
flutter-param-theta-s = 风的阻尼减半时的扭转角（教学假设）
flutter-param-slope = 最简模型：每 m/s 损失的阻尼
flutter-readout-regime = 小扭转的阻尼状态
flutter-readout-U-crit = 临界（颤振）风速 U_crit，搜索至 100 m/s
flutter-readout-zeta-eff = 小扭转的有效阻尼比 ζ_eff
flutter-readout-growth-rate = 小扭转的增长率 σ（< 0 为衰减）
flutter-readout-doubling-time = 小扭转的倍增时间
flutter-readout-frequency = 风中的扭转频率 f
flutter-readout-K = 折减频率 K = Bω/U
flutter-readout-reduced-velocity = 折减风速 U/(f·B) = 2π/K
flutter-readout-A2 = 颤振导数 A₂*(K)
flutter-readout-A3 = 颤振导数 A₃*(K)
flutter-readout-limit-deg = 极限环扭转振幅（采用假设界限 θ_s）
flutter-readout-time-to-large = 从 θ₀ 到极限环 90% 的时间
flutter-readout-amplitude-end-deg = 图末的扭转振幅
flutter-plot-derivative = 颤振导数 A₂* 与颤振阈值
flutter-plot-damping = 有效阻尼随风速的变化
flutter-plot-locus = 风速增大时的根轨迹
flutter-plot-response = 数分钟内的桥面扭转 θ(t)
flutter-preset-1 = 塔科马 1940，10 m/s（稳定）
flutter-preset-2 = 塔科马 1940，19 m/s（坍塌当天，≈ 42 mph）
flutter-preset-3 = 塔科马 1940，30 m/s 大风
flutter-preset-4 = 流线型箱梁桥面，19 m/s
flutter-preset-5 = 流线型箱梁桥面，40 m/s
flutter-preset-6 = 最简模型，19 m/s（ζ_eff = ζ_s − g·U）
flutter-table-caption = 颤振不是共振
flutter-table-column-1 = 情形
flutter-table-column-2 = 驱动因素
flutter-table-column-3 = 频率
flutter-table-column-4 = 阻尼
flutter-table-column-5 = 振幅
flutter-table-column-6 = 对策
flutter-table-resonance-1 = 受迫共振（作对比）
flutter-table-resonance-2 = 在 ωₙ 附近振荡的外力（齐步行进、发动机）
flutter-table-resonance-3 = 由外力决定；必须与 ωₙ 吻合
flutter-table-resonance-4 = 为正：将峰值限制在静态值的约 1/(2ζ) 倍
flutter-table-resonance-5 = 有界的稳态
flutter-table-resonance-6 = 调离共振，或增加阻尼
flutter-table-underdamped-1 = 风速低于 U_crit
flutter-table-underdamped-2 = 稳定的风；力矩 ∝ 扭转角速度（A₂*）和扭转角（A₃*）
flutter-table-underdamped-3 = 桥面自身的频率，被 A₃* 略微改变
flutter-table-underdamped-4 = ζ_eff > 0：A₂* 低于阈值 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = 扭转逐渐消失
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = 风速等于 U_crit
flutter-table-undamped-2 = 稳定的风；力矩 ∝ 扭转角速度（A₂*）和扭转角（A₃*）
flutter-table-undamped-3 = 桥面自身的频率
flutter-table-undamped-4 = ζ_eff = 0：极点位于虚轴上
flutter-table-undamped-5 = 扭转保持不变
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = 颤振，风速高于 U_crit
flutter-table-negatively-damped-2 = 稳定的风；运动自己产生激励
flutter-table-negatively-damped-3 = 桥面自身的频率，无需匹配
flutter-table-negatively-damped-4 = ζ_eff < 0：每个周期都有能量输入
flutter-table-negatively-damped-5 = 不断增大，直到振幅界限（或桥面）失效
flutter-table-negatively-damped-6 = A₂* 始终为负的截面：流线型、开孔或加劲桥面
### integrators

integrators-join = { "；" }
integrators-legend-dp45-order = DP45：{ $order }
integrators-overflow-note = 在 t = { $time } 处溢出
integrators-failed = 失败
integrators-stable-yes = 是
integrators-stable-no = 否
integrators-method-euler = 显式欧拉法
integrators-method-symplectic-euler = 辛欧拉法
integrators-method-heun = Heun 法
integrators-method-rk4 = RK4 法
integrators-legend-symplectic-euler = 辛欧拉 ×
integrators-legend-euler = 欧拉法
integrators-legend-heun = Heun 法
integrators-legend-dp45 = DP45 ● 步
integrators-legend-growing = { $legend } ×{ $growth }/步 ↑
integrators-legend-order = { $legend }：{ $order }
integrators-legend-no-fit = { $legend }：无拟合
integrators-legend-dp45-no-order = DP45：无阶数
integrators-series-exact = 精确解
integrators-axis-error = 误差 |x_num − x_exact|
integrators-axis-step = 步长 h
integrators-axis-max-error = 最大误差
integrators-axis-re = 实部 Re(hλ)
integrators-axis-im = 虚部 Im(hλ)
integrators-axis-evaluations = 右端函数求值次数 N
integrators-limit-up-to = 当 h ≤ { $step } 时稳定
integrators-limit-every = 对任意 h 稳定
integrators-limit-none = 对任意 h 都不稳定
integrators-method-overflows = { $method }在 t = { $time } 处溢出（每步 ×{ $growth }）
integrators-method-diverges = { $method }发散（每步 ×{ $growth }），最大误差 { $error }
integrators-method-diverges-clipped = { $method }发散（每步 ×{ $growth }，已截断），最大误差 { $error }
integrators-method-bounded = { $method }保持有界（每步 ×{ $growth }），最大误差 { $error }
integrators-dp45-words = DP45 走了 { $steps } 步（容差 { $tolerance }），最大误差 { $error }
integrators-dp45-failed = DP45 失败：{ $reason }
integrators-failed-underflow = 在 t = { $time } 处步长变得过小，无法继续推进（问题可能过于刚性或奇异）
integrators-failed-max-steps = 在 t = { $time } 处放弃，共 { $steps } 步
integrators-failed-non-finite = 在 t = { $time } 处解变为无穷大或无定义（请尝试更小的步长）
integrators-describe-response = 各方法与精确的衰减振荡对比，时长 { $duration }，h = { $step }（{ $steps } 步）。{ $methods }。图中显示精确振幅的 ±{ $range } 倍范围；超出的曲线在边缘处截断。
integrators-describe-response-last = 各方法与精确的衰减振荡对比，时长 { $duration }，h = { $step }（{ $steps } 步，最后一步为 { $last }，恰好结束于 T）。{ $methods }。图中显示精确振幅的 ±{ $range } 倍范围；超出的曲线在边缘处截断。
integrators-error-peak = { $method }：最大 { $error }，位于 t = { $time }
integrators-error-peak-growing = { $method }：最大 { $error }，位于 t = { $time }，且在增长
integrators-error-none = { $method }：没有有限误差
integrators-error-no-method = 未开启任何方法。
integrators-describe-error = 误差 |x_num − x_exact|，对数坐标，取各方法自身的网格点（h = { $step }）：{ $methods }。
integrators-describe-error-clipped = 误差 |x_num − x_exact|，对数坐标，取各方法自身的网格点（h = { $step }）：{ $methods }。超过 { $clip } 的误差在顶部截断。
integrators-fit = { $method }：拟合斜率 { $slope }（h = { $from } … { $to }）
integrators-fit-overflows = { $method }：拟合斜率 { $slope }（h = { $from } … { $to }），h ≥ { $limit } 时溢出
integrators-no-fit = { $method }：无拟合（渐近区间内的点太少）
integrators-no-fit-overflows = { $method }：无拟合（渐近区间内的点太少），h ≥ { $limit } 时溢出
integrators-slope = 斜率 { $order }
integrators-describe-convergence = { $points } 个公共检查点上的最大误差随步长 h 的变化，最多 { $levels } 个步长，从 { $from } 起逐次减半（每种方法总计最多 { $budget } 步，显式欧拉法最多 { $euler_budget } 步；更细的步长略去）。{ $methods }。每个阶数只在渐近区间内拟合，以粗线段表示：即局部斜率相差不超过 { $spread } 的最细步长，且误差低于 x₀ 的 { $ceiling }、高于 x₀ 的 1e-10。参考斜率 1 和 4 为点线；当前 h 为竖直虚线。DP45 没有单一的 h：见计算量–精度图。
integrators-off-scale = { $name } = { $value }（超出范围）
integrators-path = h 增大时 hλ 的轨迹
integrators-z-real-pair = z = hλ = { $z1 } 和 { $z2 }
integrators-region-inside = { $method }：在其稳定区域内，|R| = { $growth }，{ $limit }
integrators-region-outside = { $method }：在其稳定区域外，|R| = { $growth }，{ $limit }
integrators-describe-stability = z = hλ 复平面上的稳定区域 |R(z)| ≤ 1（各闭合曲线的内部；显式欧拉法的是圆盘 |1 + z| ≤ 1）。h = { $step } 时系统的两个极点给出 { $z }。{ $methods }。辛欧拉法不是标量映射 R(z)：它的 2×2 步进矩阵此时的谱半径为 { $radius }，{ $limit }。DP45 自行选择步长并保持稳定。
integrators-work-words = { $method }：从 { $error_first }（{ $work_first } 次求值）到 { $error_last }（{ $work_last } 次求值）
integrators-describe-work = 最大误差与所花计算量的关系，计算量以右端函数 f 的求值次数计，双对数坐标，包含所有方法：定步长方法取收敛性研究中的各步长（误差取其公共检查点），DP45 取容差 { $from } … { $to }（误差取其接受的各步）。越低越精确，越靠左越省；p 阶方法以斜率 −p 下降；DP45 的各次计算中，由容差决定步长的画为圆点，由稳定性决定步长的画为叉号。{ $methods }。
integrators-provisional = 临时结果：基于粗略研究（每种方法最多 { $budget } 步，显式欧拉 { $euler_budget } 步；DP45 至 { $tol }），完整研究（{ $full_budget } 与 { $full_euler_budget } 步；DP45 至 { $full_tol }）仍在计算中。{ $description }
integrators-runs-provisional = 临时结果：目前已算到 t = { $until }（共 { $duration }），其余部分仍在计算中。{ $description }
integrators-dp45-stability-runs = 步长由稳定性决定的计算（超过 { $share } 的步长达到其最大稳定步长的 { $fraction } 或以上）：{ $count }/{ $runs }
integrators-dp45-order = DP45 观测阶数 { $order }（在 { $from } … { $to } 次求值范围内拟合，此处步长由容差决定）；{ $runs }
integrators-dp45-no-order = DP45 没有观测阶数：步长由稳定性决定，或渐近区间内剩余的计算太少；{ $runs }
integrators-title = 数值积分方法及其误差
integrators-summary = 用显式欧拉法、辛欧拉法、Heun 法（RK2）和经典 RK4 以固定步长 h 积分自由振子，并用自适应步长的 Dormand–Prince 5(4) 积分，各自与精确解比较。单步法每一步把每个模态乘以 R(hλ)：当 |R| > 1 时，无论方法对方程拟合得多好，数值都会增长，这就是为什么除非 h < 2ζ/ωₙ，显式欧拉法会让轻阻尼振子发散。方法稳定时，把 h 减半会使误差除以 2^p，其中 p 是方法的收敛阶：收敛图测量的就是 p。关闭某个方法会隐藏其曲线，但其读数仍会计算。
integrators-param-zeta = 阻尼比
integrators-param-wn = 固有频率
integrators-param-h = 步长
integrators-param-T = 时长
integrators-param-x0 = 初始位移
integrators-param-tol = DP45 容差（相对；绝对容差为 tol·x₀）
integrators-param-euler = 显式欧拉法
integrators-param-symplectic-euler = 辛欧拉法
integrators-param-heun = Heun 法（RK2）
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4)，自适应
integrators-readout-h-used = 实际步长（最后一步除外）
integrators-readout-h-last = 最后一步，使计算结束于 T
integrators-readout-max-err-euler = 最大误差，显式欧拉法
integrators-readout-max-err-symplectic-euler = 最大误差，辛欧拉法
integrators-readout-max-err-heun = 最大误差，Heun 法
integrators-readout-max-err-rk4 = 最大误差，RK4
integrators-readout-max-err-dp45 = 最大误差，DP45
integrators-readout-order-euler = 拟合阶数，显式欧拉法
integrators-readout-order-symplectic-euler = 拟合阶数，辛欧拉法
integrators-readout-order-heun = 拟合阶数，Heun 法
integrators-readout-order-rk4 = 拟合阶数，RK4
integrators-readout-order-dp45 = 观测阶数，DP45（误差对 f 求值次数，此处步长由容差决定）
integrators-readout-stable-euler = 此 h 下是否稳定，显式欧拉法
integrators-readout-stable-symplectic-euler = 此 h 下是否稳定，辛欧拉法
integrators-readout-stable-heun = 此 h 下是否稳定，Heun 法
integrators-readout-stable-rk4 = 此 h 下是否稳定，RK4
integrators-readout-growth-euler = 每步增长 |R(hλ)|，显式欧拉法
integrators-readout-growth-symplectic-euler = 每步增长（谱半径），辛欧拉法
integrators-readout-growth-heun = 每步增长 |R(hλ)|，Heun 法
integrators-readout-growth-rk4 = 每步增长 |R(hλ)|，RK4
integrators-readout-steps-dp45 = DP45 接受的步数
integrators-plot-response = 数值解与精确解 x(t)
integrators-plot-error = 误差随时间的变化
integrators-plot-convergence = 收敛性：最大误差随步长 h 的变化
integrators-plot-work = 计算量–精度：最大误差随 f 求值次数的变化
integrators-plot-stability = 稳定区域与 z = hλ
integrators-preset-1 = 轻阻尼，h = 0.3 s
integrators-preset-2 = 欧拉法刚好稳定，h = 0.04 s
integrators-preset-3 = RK4 超出其极限，h = 1.6 s
integrators-preset-4 = 无阻尼，h = 0.1 s
integrators-preset-5 = 刚性过阻尼 ζ = 2，ωₙ = 20
integrators-table-caption = 各种方法
integrators-table-column-1 = 方法
integrators-table-column-2 = 阶数 p
integrators-table-column-3 = 每步 f 求值次数
integrators-table-column-4 = 放大因子 R(z)
integrators-table-column-5 = 用于无阻尼振子时
integrators-table-euler-1 = 显式欧拉法
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = 总是增长：|R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = 辛欧拉法
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = 2×2 矩阵，而非标量 R
integrators-table-symplectic-euler-5 = ωh ≤ 2 时能量误差有界
integrators-table-heun-1 = Heun 法（RK2）
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = 缓慢增长：|R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = 经典 RK4
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = ωh ≤ 2√2 时略有衰减
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6（首级即上一步末级，FSAL）
integrators-table-dp45-4 = 自适应：h 随误差估计调整
integrators-table-dp45-5 = 稳定：被拒绝的步会缩小 h

### nonlinear

nonlinear-effect-linear = 线性
nonlinear-effect-hardening = 渐硬弹簧
nonlinear-effect-softening = 渐软弹簧
nonlinear-effect-stick-slip = 粘滑
nonlinear-effect-bump-stop = 限位块撞击
nonlinear-effect-asymmetric = 非对称阻尼器
nonlinear-effect-several = 多种同时存在
nonlinear-effect-escaped = 逃逸
nonlinear-join = { "；" }
nonlinear-differ = 最大相差 { $deviation }，出现在 t = { $time }
nonlinear-first-swing = 第一次摆动 { $nonlinear }，线性为 { $linear }（比值 { $ratio }）
nonlinear-sticks-at = 从 { $time } 起摩擦力把质量保持在 { $position }
nonlinear-escapes = 非线性计算在 { $time } 时离开图形范围（|x| > { $limit }）
nonlinear-describe-response = { $effect }：两者同时出发；{ $clauses }。
nonlinear-describe-phase = 相平面：两条轨迹都从 x = { $x0 }、v = { $v0 } 出发。线性轨迹螺旋趋向（{ $x_linear }，{ $v_linear }）；非线性轨迹终止于 x = { $x_end }、v = { $v_end }，其最大速度为 { $speed }，线性为 { $speed_linear }。
nonlinear-describe-spring = 恢复力随伸长量的变化，范围 ±{ $reach }：线性弹簧为直线 k·x；在最大行程 { $travel } 处，非线性力为 { $force }，线性为 { $linear }{ $stops ->
        [yes] ，超出 ±{ $gap } 后限位块再增加 { $rate }。
       *[no] 。
    }
nonlinear-describe-damper = 阻尼力加摩擦力随速度的变化，范围 ±{ $speed }：在 +{ $speed }（回弹）时为 { $rebound }，在 −{ $speed }（压缩）时为 { $compression }；线性模型的平均阻尼给出 ±{ $linear }{ $coulomb ->
        [yes] ；滑动摩擦在 v = 0 处造成 ±{ $friction } 的跳变，静止时静摩擦最多能保持 ±{ $holding }。
       *[no] 。
    }
nonlinear-axis-velocity-rebound = 速度 v（+ 为回弹）
nonlinear-series-stops = 限位块 ±{ $gap }
nonlinear-series-linear = 线性模型
nonlinear-series-nonlinear = 非线性（RK4）
nonlinear-marker-sticks = 粘住
nonlinear-marker-start = 起点
nonlinear-series-linear-spring = 线性 k·x
nonlinear-series-spring = k·x + k₃·x³ + 限位块
nonlinear-series-linear-damper = 线性 c̄·v
nonlinear-series-damper = 阻尼器 + 摩擦
nonlinear-schematic = t = { $time } 时的四分之一车辆：悬架伸长 { $extension }{ $stops ->
        [pressing] ，正压在限位块上。
        [clear] ，未接触限位块。
       *[none] 。
    }
nonlinear-title = 超越线性模型
nonlinear-summary = 真实的悬架只在小幅运动时才是线性的。这里的四分之一车辆模型带有三次弹簧（k₃ > 0 为渐硬，k₃ < 0 为渐软）、回弹（x′ > 0）比压缩更硬的阻尼器、关节中的库仑摩擦以及超出 ±gap 后起作用的橡胶限位块。摩擦会交替粘住和滑动：质量滑动时，摩擦以力 F_c 拖拽它；一旦停下，静摩擦最多能以 F_static（F_c 的固定倍数）将其保持住，只有弹簧拉力更大时它才会再次运动。运动用 RK4 积分，每次停止都在其步长内精确定位，并与从同一初始状态出发的线性模型 m·x″ + c̄·x′ + k·x = 0（c̄ 为平均阻尼系数）对比绘制。请观察预测在哪里失效：周期取决于振幅（渐硬弹簧使其缩短，渐软弹簧使其变长），摩擦使振幅按直线下降，然后把质量永久地保持在偏离中心的位置（粘滑），限位块把平滑的摆动变成撞击，非对称阻尼器会使平均位置偏移。默认值是一个合理的车辆角：300 kg、24 kN/m（1.4 Hz）、1 500 N·s/m 的阻尼器（ζ ≈ 0.28）和略带渐进特性的弹簧。x 是悬架相对静平衡位置的伸长量（正值 = 车身向上）。
nonlinear-param-m = 簧上质量
nonlinear-param-k = 线性弹簧刚度
nonlinear-param-k3 = 弹簧三次项系数（+ 渐硬，− 渐软）
nonlinear-param-c-comp = 压缩阻尼系数
nonlinear-param-c-reb = 回弹阻尼系数
nonlinear-param-friction = 滑动时的库仑摩擦力
nonlinear-param-stick-ratio = 静摩擦与滑动摩擦之比
nonlinear-param-gap = 限位块间隙
nonlinear-param-k-stop = 限位块刚度（0 = 无限位块）
nonlinear-param-x0 = 初始伸长量
nonlinear-param-v0 = 初始速度
nonlinear-readout-effect = 主要非线性
nonlinear-readout-period-ratio = 第一次摆动的周期比 T_nonlinear / T_linear
nonlinear-readout-max-deviation = 最大 |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = 第一个完整摆动的非线性周期（三次过零）
nonlinear-readout-period-linear = 第一个完整摆动的线性周期（= 2π/ω_d）
nonlinear-readout-max-travel = 最大 |x|（非线性）
nonlinear-readout-stick-position = 摩擦力将质量保持在
nonlinear-plot-response = 非线性与线性响应 x(t)
nonlinear-plot-phase = 相平面（x, v）
nonlinear-plot-spring = 弹簧与限位块力
nonlinear-plot-damper = 阻尼力与摩擦力
nonlinear-preset-1 = 线性（全部关闭）
nonlinear-preset-2 = 渐硬弹簧
nonlinear-preset-3 = 渐软弹簧
nonlinear-preset-4 = 摩擦粘滑
nonlinear-preset-5 = 限位块撞击
nonlinear-preset-6 = 非对称阻尼器
nonlinear-table-caption = 线性模型在哪里失效
nonlinear-table-column-1 = 非线性
nonlinear-table-column-2 = 力的规律
nonlinear-table-column-3 = 线性模型遗漏了什么
nonlinear-table-column-4 = 图中的特征
nonlinear-table-linear-1 = 无（线性）
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = 无：模型是精确的
nonlinear-table-linear-4 = 两条曲线重合
nonlinear-table-hardening-spring-1 = 渐硬弹簧
nonlinear-table-hardening-spring-2 = k·x + k₃·x³，k₃ > 0
nonlinear-table-hardening-spring-3 = 频率随振幅升高
nonlinear-table-hardening-spring-4 = 摆动大时周期较短；两条曲线逐渐分开
nonlinear-table-softening-spring-1 = 渐软弹簧
nonlinear-table-softening-spring-2 = k·x + k₃·x³，k₃ < 0
nonlinear-table-softening-spring-3 = 频率随振幅降低；超过 √(−k/k₃) 后弹簧失去支撑
nonlinear-table-softening-spring-4 = 周期较长；初始值大时可能逃逸
nonlinear-table-stick-slip-1 = 库仑摩擦
nonlinear-table-stick-slip-2 = 滑动时为 F_c·sgn(x′)；静止时最大 F_static
nonlinear-table-stick-slip-3 = 振幅每周期按直线下降约 4F_c/k，随后质量在 |k·x| ≤ F_static 处永久粘住
nonlinear-table-stick-slip-4 = 直线包络；末端平直且不在零点
nonlinear-table-bump-stop-impact-1 = 限位块
nonlinear-table-bump-stop-impact-2 = 超出 ±gap 后为 k_stop·(|x| − gap)
nonlinear-table-bump-stop-impact-3 = 突然的刚性接触：力大、反向快
nonlinear-table-bump-stop-impact-4 = 峰值在 ±gap 处被削平；相图回线出现折角
nonlinear-table-asymmetric-damper-1 = 非对称阻尼器
nonlinear-table-asymmetric-damper-2 = 回弹时为 c_r·x′，压缩时为 c_c·x′
nonlinear-table-asymmetric-damper-3 = 平均位置偏移（“顶升”效应）且半周期不相等
nonlinear-table-asymmetric-damper-4 = 衰减不对称；相图螺线偏离中心
nonlinear-table-several-at-once-1 = 多种同时存在
nonlinear-table-several-at-once-2 = 以上各项之和
nonlinear-table-several-at-once-3 = 各效应相互叠加并相互作用
nonlinear-table-several-at-once-4 = 见各行
nonlinear-table-escaped-1 = 超出极限的渐软弹簧
nonlinear-table-escaped-2 = 当 |x| > √(−k/k₃) 时 k·x + k₃·x³ < 0
nonlinear-table-escaped-3 = 模型不再能描述悬架
nonlinear-table-escaped-4 = 当 |x| 超过 1 m 时计算被截断

### uncertainty

uncertainty-quantity-zeta = 阻尼比 ζ
uncertainty-quantity-f0 = 固有频率 f0
uncertainty-quantity-q = 品质因数 Q
uncertainty-quantity-bandwidth = 半功率带宽
uncertainty-quantity-settling-time = 自由响应调节时间（±5 %）
uncertainty-hist-title = 蒙特卡罗：{ $quantity }
uncertainty-draws-provisional = { $draws }（{ $full } 计算中）
uncertainty-band-nominal-mass = 标称 m
uncertainty-band-lowest-corner = ζ 最小的角点
uncertainty-band-nominal = 标称
uncertainty-band-highest-corner = ζ 最大的角点
uncertainty-never = 永不
uncertainty-band-suspension = 从 { $start } 出发的自由响应，簧上质量分别为 +{ $percent } %、标称值和 −{ $percent } %
uncertainty-band-rlc = 电容电压从 1 V 出发，分别取容差盒中 ζ 最小的角点、标称值和 ζ 最大的角点
uncertainty-ignored-rlc = RLC 的滑块不起作用。
uncertainty-ignored-suspension = 悬架的滑块不起作用。
uncertainty-zeta-undefined = ζ 在范围的一端无定义
uncertainty-zeta-spans = ζ 的范围为 { $low }–{ $high }
uncertainty-describe-band = { $what }：{ $zeta }；5 % 调节时间（叉号）分别为 { $first }、{ $second } 和 { $third }。{ $ignored }
uncertainty-dist-normal = 正态（容差 = 3σ）
uncertainty-dist-uniform = 均匀
uncertainty-spec-zeta = 图中标出了 ζ 的规格窗口 { $low }–{ $high }；{ $share } 的抽样满足全部规格。
uncertainty-spec-settling-time = 图中标出了规格限值 { $limit }。
uncertainty-no-finite = 没有任何抽样得到有限的{ $quantity }。
uncertainty-describe-histogram = { $quantity }的直方图，共 { $draws } 次{ $distribution }抽样：从 { $low } 到 { $high }，第 5 百分位数 { $p5 }，第 95 百分位数 { $p95 }。{ $marked ->
        [yes] { $spec }
       *[no] {""}
    }
uncertainty-provisional-title = { $title }（临时）
uncertainty-provisional-description = 临时结果：基于前 { $shown } 次抽样，共 { $full } 次的计算仍在进行。{ $description }
uncertainty-axis-capacitor-voltage = 电容电压 v_C
uncertainty-settling-band = 5 % 调节带
uncertainty-axis-draws = 抽样数
uncertainty-series-bins = 每个区间的抽样数（{ $bins } 个区间）
uncertainty-no-finite-values = 没有有限值
uncertainty-spec-limit = 规格限值
uncertainty-percentiles = 第 5 / 95 百分位数
uncertainty-title = 容差分析
uncertainty-summary = 实际元件并不恰好等于其标称值。请选择系统：四分之一车辆（簧上质量 m、弹簧 k，阻尼器按标称质量下的 ζ 设定；车辆载重变化时质量在 ±dm 内变化）或串联 RLC 回路（R、L、C 分别在 ±dR、±dL、±dC 内）。只有所选系统的滑块起作用；另一组将被忽略。ζ、ωₙ 和 Q 的精确范围由容差盒的各角点得到。蒙特卡罗计算抽取 N 个设计（带随机种子，相同种子给出相同结果）：在容差内均匀分布，或以容差为 3σ 的正态分布。合格率是 ζ 落在规格窗口内、且 5 % 调节时间（从静止释放）不超过限值的抽样所占的比例。
uncertainty-param-system = 系统
uncertainty-param-system-suspension = 四分之一车辆悬架
uncertainty-param-system-rlc = 串联 RLC
uncertainty-param-m = 悬架：簧上质量
uncertainty-param-k = 悬架：弹簧刚度
uncertainty-param-zeta = 悬架：标称质量下的设计 ζ
uncertainty-param-dm = 悬架：质量容差 ±
uncertainty-param-R = RLC：电阻
uncertainty-param-L = RLC：电感
uncertainty-param-C = RLC：电容
uncertainty-param-dR = RLC：电阻容差 ±
uncertainty-param-dL = RLC：电感容差 ±
uncertainty-param-dC = RLC：电容容差 ±
uncertainty-param-dist = 元件分布
uncertainty-param-dist-uniform = 在 ±容差内均匀分布
uncertainty-param-dist-normal = 正态分布，容差 = 3σ
uncertainty-param-N = 蒙特卡罗抽样数
uncertainty-param-seed = 随机种子
uncertainty-param-zeta-lo = 规格：ζ 下限
uncertainty-param-zeta-hi = 规格：ζ 上限
uncertainty-param-ts-max = 规格：最长调节时间
uncertainty-param-hist = 第二个直方图
uncertainty-param-hist-zeta = 阻尼比 ζ
uncertainty-param-hist-f0 = 固有频率 f0
uncertainty-param-hist-q = 品质因数 Q
uncertainty-param-hist-bandwidth = 带宽
uncertainty-param-hist-settling-time = 调节时间
uncertainty-readout-zeta-min = ζ，最小值（精确）
uncertainty-readout-zeta-max = ζ，最大值（精确）
uncertainty-readout-wn-min = ωₙ，最小值（精确）
uncertainty-readout-wn-max = ωₙ，最大值（精确）
uncertainty-readout-Q-min = Q，最小值（精确）
uncertainty-readout-Q-max = Q，最大值（精确）
uncertainty-readout-yield = 合格率（满足规格）
uncertainty-readout-zeta-p5 = ζ，第 5 百分位数
uncertainty-readout-zeta-p95 = ζ，第 95 百分位数
uncertainty-readout-Q-p5 = Q，第 5 百分位数
uncertainty-readout-Q-p95 = Q，第 95 百分位数
uncertainty-readout-draws = 抽样数
uncertainty-readout-compute-time = 蒙特卡罗计算时间
uncertainty-plot-band = 容差范围内的自由响应带
uncertainty-plot-zeta-hist = 蒙特卡罗：阻尼比 ζ
uncertainty-plot-hist = 蒙特卡罗：所选物理量
uncertainty-preset-1 = ζ = 1 的设计，质量 ±10 %
uncertainty-preset-2 = ζ = 0.7 的设计，质量 ±10 %
uncertainty-preset-3 = RLC，元件精度 5 %
uncertainty-preset-4 = RLC，元件精度 20 %
# Zeta Lab — 简体中文. Ids and variables as in en.ftl.

## 页面

page-skip = 跳到演示
page-demo = 演示
page-share = 分享／嵌入
page-loading = 正在加载求解器…
page-footer = Zeta Lab——本页的每个数字都由 Rust（编译为 WebAssembly）根据解析解计算得出。
page-parameters = 参数
page-readouts = 读数
page-about = 关于本演示
page-plot-in-view = 当前图表
page-presets = 预设
page-reset = 恢复默认值
page-exact-value = 精确值
page-export-group = 导出{ $plot }
page-download = 将{ $plot }下载为 { $format }
page-play = 播放
page-pause = 暂停
page-sound-on = 声音开
page-sound-off = 声音关
page-sound-hint = 聆听 x(t)：音高随位移变化
page-anim-time = 动画时间
page-time-words = 时间 { $t } 秒
page-schematic = 动画示意图
page-dismiss = 关闭通知
page-failed = 出现错误，演示已重新启动：{ $text }
page-no-demo = 没有名为“{ $id }”的演示；显示 { $fallback }。
page-no-wasm = 无法加载求解器（{ $text }）。本页需要 WebAssembly。
page-module-failed = 无法加载页面的这一部分（{ $text }）。请检查网络连接后重试。
page-copy = 复制
page-equation = 方程
page-tour-head = 论文，逐图核对
page-tour-open = 在演示中打开此状态
page-tour-paper = 论文给出
page-tour-app = 本应用计算得
page-tour-confirmed = 一致。
page-tour-differs = 不一致。
page-tour-pending = 核对中…
page-copied = 已复制
page-copy-manual = 请选中并复制（Ctrl+C）
page-share-title = 分享或嵌入“{ $title }”
page-embed-view = {" "}嵌入视图（无网站页眉）
page-autoplay = {" "}自动播放动画
page-theme = 主题{" "}
page-width = {" "}宽度{" "}
page-height = {" "}高度{" "}
page-sliders-shown = 显示的滑块
page-sliders-locked = 锁定的滑块
page-plots-shown = 显示的图表
page-link = 链接
page-embed-code = 嵌入代码
page-preview = 嵌入演示的预览
page-close = 关闭
page-language = 语言
page-language-nav = 语言
page-demos-nav = 演示
page-no-script = Zeta Lab 需要 JavaScript 和 WebAssembly。
page-catalogue-failed = 无法加载{ $name }语言包（{ $text }）；页面仍以英文显示。
page-provisional = { $value }（暂定）
page-study-progress = 正在计算完整结果
page-readouts-shown = 显示的读数
page-state-token = 状态令牌
page-theme-auto = 自动
page-theme-light = 浅色
page-theme-dark = 深色
page-theme-projector = 投影（高对比度）
page-share-visitor-language = 访问者的语言
page-share-language = {" "}语言{" "}
page-share-fullscreen = {" "}全屏按钮
page-share-ranges = 滑块的范围和步长（留空则保留声明值）
page-share-col-slider = 滑块
page-share-col-from = 最小值
page-share-col-to = 最大值
page-share-col-step = 步长
page-share-range-from = { $label }：最小值
page-share-range-to = { $label }：最大值
page-share-range-step = { $label }：步长
page-share-predict-task = 预测任务
page-share-none = 无
page-share-predict = 学生预测{" "}
page-share-predict-within = {" "}容差{" "}
page-share-presets = 教师预设（包含在链接中）
page-share-preset-example = 例如：轻阻尼
page-share-preset-add = 添加屏幕上的数值
page-share-preset-format = 格式：名称:键=值,键=值; 下一个名称:…
page-share-preset-default = 预设 { $n }
page-share-preset-name = 名称{" "}
page-share-preset-list = 预设{" "}
page-lecturer-presets = 教师预设
page-full-screen = 全屏
page-exit-full-screen = 退出全屏
page-no-stamp = 此文件不含 Zeta Lab 视图（只有 Zeta Lab 导出的 PNG、SVG 和 CSV 才含有）。
page-token-invalid = 此保存的视图不是 Zeta Lab 状态令牌。
page-token-version = 此保存的视图的格式版本为“{ $version }”，本页无法读取；未做任何更改。
page-token-damaged = 此保存的视图已损坏，无法读取；未做任何更改。
page-token-no-demo = 此保存的视图指向本页没有的演示（“{ $demo }”）；未做任何更改。
page-token-other-version-missing = 此保存的视图来自另一版本的 Zeta Lab：其中没有 { $missing }，已使用默认值。
page-token-other-version-unknown = 此保存的视图来自另一版本的 Zeta Lab：此处不认识 { $unknown }，已忽略。
page-token-other-version-both = 此保存的视图来自另一版本的 Zeta Lab：其中没有 { $missing }，已使用默认值；此处不认识 { $unknown }，已忽略。
page-predict-title = 先预测
page-predict-hint = 在你作出预测之前，图表和“{ $label }”保持隐藏。输入你的预测并按回车键。
page-predict-field = 你对“{ $label }”的预测
page-predict-field-unit = 你对“{ $label }”的预测（{ $unit }）
page-predict-reveal = 揭晓
page-predict-nan = “{ $text }”不是数字。请输入数字，例如 { $example }。
page-predict-undefined = 在这些参数下“{ $label }”没有定义；请修改参数后重试。
page-predict-result-inside = 你预测的是 { $p }；“{ $label }”为 { $v }：{ $how }，在容差 { $tol } 之内。
page-predict-result-outside = 你预测的是 { $p }；“{ $label }”为 { $v }：{ $how }，超出容差 { $tol }。
page-predict-exact = 完全正确
page-predict-high = 偏高 { $d }
page-predict-low = 偏低 { $d }

## 图表

plot-clipped = 已截断：部分数值超出坐标轴范围

## 共用词：坐标轴、阻尼状态

axis-time = 时间 t
axis-displacement = 位移 x
axis-extension = 伸长量 x
axis-force = 力 F
axis-velocity = 速度 v
axis-real-part = 实部 Re s
axis-imaginary-part = 虚部 Im s
regime-undamped = 无阻尼
regime-underdamped = 欠阻尼
regime-critically-damped = 临界阻尼
regime-overdamped = 过阻尼
regime-negatively-damped = 负阻尼
regime-neutral = 中性
regime-divergent = 发散

## 演示

## 教师指南（docs/embedding.md 与 docs/parameters.<tag>.md）

guide-parameters-heading = 各演示的参数
guide-parameters-note = 各演示的 URL 参数，用于链接和嵌入（参见英文指南 docs/embedding.md）。由 Rust 声明和本语言的目录生成；若此列表与代码不符，测试将失败。
guide-column-key = 键
guide-column-quantity = 物理量
guide-column-unit = 单位
guide-column-range = 范围
guide-column-default = 默认值
guide-log = 对数
guide-readouts-plots = 读数（`data-readout`）：{ $readouts }。图（`plots=`）：{ $plots }。

### design

design-map-title = { $metric ->
        [settling-time] 调节时间（x₀ 的 ±{ $band }）
        [peak-rebound] 最大回弹（x₀ 的 %）
        [accel-rms] a_w（W_k）
       *[peak-transmissibility] 最大传递率 |X/U|
    }：{ $low } → { $high }
design-bar-label = { $metric ->
        [settling-time] 调节时间（x₀ 的 ±{ $band }）[s]
        [peak-rebound] 最大回弹 [x₀ 的 %]
        [accel-rms] a_w（W_k 加权均方根）[m/s²]
       *[peak-transmissibility] 最大传递率 |X/U| [m/m]
    }{ $scale ->
        [log] ，对数色标
       *[linear] {""}
    }
design-axis-spring-rate = 弹簧刚度 k
design-axis-damper-rate = 阻尼系数 c
design-axis-settling-time = 进入 x₀ 的 ±{ $band } 误差带的调节时间
design-axis-comfort = a_w（W_k 加权均方根）
design-marker-selected = 选定
design-marker-settled = 已稳定
design-series-column = k = { $k }，c 变化
design-series-pareto-front = 帕累托前沿
design-series-band = 误差带：x₀ 的 ±{ $band }
design-series-fastest = 网格中最快的设计
design-series-selected = 选定设计
design-road = 以 { $speed } 行驶于 ISO 8608 { $class } 级路面
design-with-road = { $value }（{ $class } 级路面，{ $speed }）
design-grid-size = { $n } × { $n } = { $cells }
design-grid-size-provisional = { $n } × { $n } = { $cells }（{ $full } × { $full } 计算中）
design-map-lowest = 最小值 { $value }，位于 k = { $k }、c = { $c }
design-map-no-cell = 没有任何单元格有定义
design-map-selected-settles = 选定设计（ζ = { $zeta }）进入 x₀ 的 ±{ $band } 误差带的调节时间为 { $time }
design-map-selected-unsettled = 选定设计（ζ = { $zeta }）不能稳定
design-map-no-selection = 未选定有效设计
design-describe-map = { $metric ->
        [settling-time] 从 x₀ = { $x0 } 释放的自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间
        [peak-rebound] 从 x₀ = { $x0 } 释放的自由响应的最大回弹（以 x₀ 的 % 计）
        [accel-rms] 两自由度车辆（车轮 { $wheel }，轮胎 { $tyre }）{ $road }时的稳态舒适性指标 a_w（W_k 加权车身加速度均方根）
       *[peak-transmissibility] 最大传递率 |X/U|
    }，k 范围 { $k_span }，c 范围 { $c_span }（{ $grid } × { $grid } 网格，m = { $mass }）：{ $lowest }；{ $selected }{ $outside ->
        [yes] （在图外）
       *[no] {""}
    }。颜色从深紫色（{ $low }）到黄色（{ $high }）{ $scale ->
        [log] ，对数色标
       *[linear] {""}
    }。虚线为 ζ = { $z1 }、{ $z2 }、{ $z3 }、{ $z4 } 和 { $z5 } 的等 ζ 线；× 标出最小值单元格，● 标出选定设计。
design-describe-pareto = 帕累托前沿共有 { $count } 个非劣设计：从最快的设计（进入 x₀ 的 ±{ $band } 误差带的调节时间为 { $fast_time }，a_w = { $fast_accel }）到最平顺的设计（{ $smooth_time }，a_w = { $smooth_accel }）。{ $selected }舒适性 a_w：两自由度车辆{ $road }时 W_k 加权的车身加速度均方根。
design-pareto-selected = 选定设计进入 x₀ 的 ±{ $band } 误差带的调节时间为 { $time }，a_w = { $accel }。
design-pareto-selected-unsettled = 选定设计没有调节时间。
design-pareto-empty = 网格中没有同时具有调节时间和舒适性指标 a_w 的设计。
design-describe-response = 选定设计（ζ = { $zeta }）在 x₀ = { $x0 } 处由静止释放（自由响应，不是阶跃响应）：回弹为 x₀ 的 { $rebound }，{ $time } 后保持在 x₀ 的 ±{ $band } 以内。
design-describe-response-fastest = 选定设计（ζ = { $zeta }）在 x₀ = { $x0 } 处由静止释放（自由响应，不是阶跃响应）：回弹为 x₀ 的 { $rebound }，{ $time } 后保持在 x₀ 的 ±{ $band } 以内；网格中最快的设计（k = { $k }，c = { $c }）的调节时间为 { $fastest_time }。
design-response-unsettled = 选定设计不能稳定。
design-provisional = 临时结果：基于 { $coarse } × { $coarse } 的粗网格，{ $full } × { $full } 的扫描仍在计算中。{ $description }
design-title = 设计空间（k, c）
design-summary = 图中每个单元格都是一个四分之一车辆（簧上质量 m 支承在弹簧 k 和阻尼器 c 上），按所选指标着色：从 x₀ = 60 mm 处由静止释放的自由响应的调节时间和最大回弹（不是阶跃响应：误差带和回弹都相对于 x₀），最大传递率，或按 ISO 2631-1 衡量的乘坐舒适性：a_w，即经 W_k 滤波器加权的车身加速度均方根（反映坐着的人对各频率振动的感受程度），为车辆以速度 V 行驶于随机 ISO 8608 路面时的稳态值。计算舒适性时，每个单元格是两自由度车辆（该车身装在下方设定的车轮 m_u 和轮胎 k_t 上，由李雅普诺夫方程求解）：对同一辆车，结果与 quarter-car-2dof 演示相同；读数还给出未加权的均方根。虚线连接阻尼比 ζ = c/(2√(km)) 相等的设计。帕累托前沿包含在舒适性和调节时间两方面都不会被其他任何设计同时超越的设计。点击图（或前沿上的一点）选择设计；改变质量可以看到整个图随之移动。
design-param-m = 簧上质量
design-param-mu = 舒适性：车轮（簧下）质量
design-param-kt = 舒适性：轮胎刚度
design-param-metric = 图中指标
design-param-metric-settling-time = 调节时间（自由响应）
design-param-metric-peak-rebound = 最大回弹（自由响应）
design-param-metric-accel-rms = 舒适性 a_w（W_k 加权车身加速度均方根）
design-param-metric-peak-transmissibility = 最大传递率 |X/U|
design-param-band = 误差带，x₀ 的 ± %（自由响应）
design-param-road = 路面（ISO 8608）
design-param-road-a = A 级（很好）
design-param-road-b = B 级（好）
design-param-road-c = C 级（一般）
design-param-road-d = D 级（差）
design-param-V = 舒适性：车速
design-param-k-min = 图：最小弹簧刚度
design-param-k-max = 图：最大弹簧刚度
design-param-c-min = 图：最小阻尼系数
design-param-c-max = 图：最大阻尼系数
design-param-k = 选定弹簧刚度
design-param-c = 选定阻尼系数
design-param-n = 每轴网格单元数
design-readout-k = 选定弹簧刚度 k
design-readout-c = 选定阻尼系数 c
design-readout-zeta = 阻尼比 ζ
design-readout-settling-time = 进入 x₀ 的 ± 误差带的调节时间（自由响应）
design-readout-overshoot = 最大回弹，x₀ 的 %（自由响应）
design-readout-accel-rms = a_w：按 ISO 2631-1 W_k 加权的车身加速度均方根（两自由度车辆，以车速 V 在 ISO 8608 路面上稳态行驶）
design-readout-accel-unweighted = 车身加速度均方根，未加权（同一车辆和路面）
design-readout-grid-size = 网格大小（单元数）
design-readout-compute-time = 扫描计算时间
design-plot-map = (k, c) 上的指标及等 ζ 线
design-plot-pareto = 舒适性与调节时间：帕累托前沿
design-plot-response = 选定设计：自由响应 x(t)
design-preset-1 = 调节时间图，300 kg，ζ ≈ 0.37
design-preset-2 = 满载车辆 500 kg，部件相同
design-preset-3 = C 级路面上的舒适性图
design-preset-4 = 最大回弹图，ζ = 0.7 的设计
design-preset-5 = 细网格 160 × 160

## 提示（无法使用的参数值）

notice-value = { $problem ->
        [toggle] { $label }（{ $key }）：“{ $value }”不是开或关；改用默认值。
        [option] { $label }（{ $key }）：“{ $value }”不是 { $options } 之一；改用默认值。
        [number] { $label }（{ $key }）：“{ $value }”不是数字；改用默认值 { $default }。
        [range-empty] { $label }（{ $key }）：范围“{ $value }”在 { $min } … { $max } 内为空；保留完整范围。
        [range-not-two-numbers] { $label }（{ $key }）：范围“{ $value }”不是“下限,上限”两个数；保留完整范围。
        [step] { $label }（{ $key }）：步长“{ $value }”不是 0 到 { $span } 之间的数；保留 { $step }。
       *[range] { $label }（{ $key }）= { $value } 超出 { $min } … { $max }{ $unit }；改用 { $used }。
    }

## 导出文件

export-csv-heading = Zeta Lab，演示 { $demo }：{ $title }
export-series = 序列 { $n }


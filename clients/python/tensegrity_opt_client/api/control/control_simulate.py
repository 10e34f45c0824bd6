from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.simulation_out import SimulationOut
from ...models.simulation_request import SimulationRequest
from ...types import Response


def _get_kwargs(
    *,
    body: SimulationRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/control/simulate",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | SimulationOut | None:
    if response.status_code == 200:
        response_200 = SimulationOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | SimulationOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: SimulationRequest,
) -> Response[ErrorOut | SimulationOut]:
    """Quasi-static simulation under sampled inputs, with the snaps at folds

     The chain driven by time series of its inputs over samples `k = 0 .. K-1`
    (`tensegrity_opt.simulate`): the rest lengths `preloads` (K, n, 2) (default the chain's own), and a
    dead tip load `loads` (K, 2) (`tip: free`, default zero) or a tip deflection `targets` (K, 2) (`tip:
    held`, required). Between samples the inputs move linearly and the configuration follows its branch
    by continuation; where the branch loses stability (a fold, or a branch point) the arm snaps: the new
    state is reached by the gradient flow from there (an overdamped arm), each snap an event with the
    fold and landing configurations and the energy released. It ends early at a joint's range bound
    (`joint_limit`) or the workspace edge, keeping the samples done. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` samples (default 2000; above: 422 `too_many_steps` naming the
    field), chains of up to 64 segments (longer: 422 `invalid_parameter` on `manipulator.n`). The
    simulation stops shortly before the server's time limit and answers the samples done (200, `status:
    "time_limit"`, `success: false`) instead of a 504. About 1 ms a sample without a snap (n = 3), tens
    of milliseconds a snap.

    Args:
        body (SimulationRequest): Quasi-static simulation under sampled preloads and a tip load or
            deflection (`tensegrity_opt.simulate`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | SimulationOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: SimulationRequest,
) -> ErrorOut | SimulationOut | None:
    """Quasi-static simulation under sampled inputs, with the snaps at folds

     The chain driven by time series of its inputs over samples `k = 0 .. K-1`
    (`tensegrity_opt.simulate`): the rest lengths `preloads` (K, n, 2) (default the chain's own), and a
    dead tip load `loads` (K, 2) (`tip: free`, default zero) or a tip deflection `targets` (K, 2) (`tip:
    held`, required). Between samples the inputs move linearly and the configuration follows its branch
    by continuation; where the branch loses stability (a fold, or a branch point) the arm snaps: the new
    state is reached by the gradient flow from there (an overdamped arm), each snap an event with the
    fold and landing configurations and the energy released. It ends early at a joint's range bound
    (`joint_limit`) or the workspace edge, keeping the samples done. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` samples (default 2000; above: 422 `too_many_steps` naming the
    field), chains of up to 64 segments (longer: 422 `invalid_parameter` on `manipulator.n`). The
    simulation stops shortly before the server's time limit and answers the samples done (200, `status:
    "time_limit"`, `success: false`) instead of a 504. About 1 ms a sample without a snap (n = 3), tens
    of milliseconds a snap.

    Args:
        body (SimulationRequest): Quasi-static simulation under sampled preloads and a tip load or
            deflection (`tensegrity_opt.simulate`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | SimulationOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: SimulationRequest,
) -> Response[ErrorOut | SimulationOut]:
    """Quasi-static simulation under sampled inputs, with the snaps at folds

     The chain driven by time series of its inputs over samples `k = 0 .. K-1`
    (`tensegrity_opt.simulate`): the rest lengths `preloads` (K, n, 2) (default the chain's own), and a
    dead tip load `loads` (K, 2) (`tip: free`, default zero) or a tip deflection `targets` (K, 2) (`tip:
    held`, required). Between samples the inputs move linearly and the configuration follows its branch
    by continuation; where the branch loses stability (a fold, or a branch point) the arm snaps: the new
    state is reached by the gradient flow from there (an overdamped arm), each snap an event with the
    fold and landing configurations and the energy released. It ends early at a joint's range bound
    (`joint_limit`) or the workspace edge, keeping the samples done. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` samples (default 2000; above: 422 `too_many_steps` naming the
    field), chains of up to 64 segments (longer: 422 `invalid_parameter` on `manipulator.n`). The
    simulation stops shortly before the server's time limit and answers the samples done (200, `status:
    "time_limit"`, `success: false`) instead of a 504. About 1 ms a sample without a snap (n = 3), tens
    of milliseconds a snap.

    Args:
        body (SimulationRequest): Quasi-static simulation under sampled preloads and a tip load or
            deflection (`tensegrity_opt.simulate`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | SimulationOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: SimulationRequest,
) -> ErrorOut | SimulationOut | None:
    """Quasi-static simulation under sampled inputs, with the snaps at folds

     The chain driven by time series of its inputs over samples `k = 0 .. K-1`
    (`tensegrity_opt.simulate`): the rest lengths `preloads` (K, n, 2) (default the chain's own), and a
    dead tip load `loads` (K, 2) (`tip: free`, default zero) or a tip deflection `targets` (K, 2) (`tip:
    held`, required). Between samples the inputs move linearly and the configuration follows its branch
    by continuation; where the branch loses stability (a fold, or a branch point) the arm snaps: the new
    state is reached by the gradient flow from there (an overdamped arm), each snap an event with the
    fold and landing configurations and the energy released. It ends early at a joint's range bound
    (`joint_limit`) or the workspace edge, keeping the samples done. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` samples (default 2000; above: 422 `too_many_steps` naming the
    field), chains of up to 64 segments (longer: 422 `invalid_parameter` on `manipulator.n`). The
    simulation stops shortly before the server's time limit and answers the samples done (200, `status:
    "time_limit"`, `success: false`) instead of a 504. About 1 ms a sample without a snap (n = 3), tens
    of milliseconds a snap.

    Args:
        body (SimulationRequest): Quasi-static simulation under sampled preloads and a tip load or
            deflection (`tensegrity_opt.simulate`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | SimulationOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
